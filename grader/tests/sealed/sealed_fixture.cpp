// A test executable whose tests behave the way a student's code can make a test behave: pass,
// fail, leave with exit(0) or _Exit(0) in the middle, print GoogleTest's pass and skip lines,
// write a forged report line to every descriptor it can, or skip. Not a test of the project: the
// grader's sealed-report test runs each of these and checks the verdict.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

TEST(Fixture, Passes) { EXPECT_EQ(1 + 1, 2); }

TEST(Fixture, Fails) { EXPECT_EQ(1 + 1, 3); }

TEST(Fixture, ExitsZero) {
  std::exit(0);
}

TEST(Fixture, QuickExitsZero) { std::_Exit(0); }

TEST(Fixture, PrintsFakePassAndSkipLines) {
  std::printf("[       OK ] Fixture.PrintsFakePassAndSkipLines (0 ms)\n");
  std::printf("[  SKIPPED ] Fixture.PrintsFakePassAndSkipLines\n");
  std::printf("[  PASSED  ] 1 test.\n");
  std::fflush(stdout);
  std::_Exit(0);
}

TEST(Fixture, ForgesReportLines) {
  // Without the nonce it can only guess one: every descriptor gets a pass line.
  for (int fd = 3; fd < 64; ++fd) {
    std::string line = "PTREPORT 00000000000000000000000000000000 test Fixture.ForgesReportLines passed\n";
    (void)!write(fd, line.data(), line.size());
  }
  EXPECT_TRUE(false);
}

TEST(Fixture, Skips) { GTEST_SKIP() << "a course scene is not there"; }

TEST(Fixture, Crashes) { std::abort(); }
