// The grader counts a test from its sealed report, never from an exit code or printed lines: a
// test that leaves with exit(0) or _Exit(0), prints GoogleTest's pass or skip lines or forges a
// report line fails; and a render's file is read only if the render wrote it itself.
#include "grader/sandbox.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"

namespace pt::grader {
namespace {

const char* kFixture = GRADER_SEALED_FIXTURE;

/// A uid slot of this test process's own: ctest runs these tests side by side (-j2), and as root
/// a sandbox ends every process of its uid when a check ends, so two tests sharing a slot would
/// end each other's children (a test failed that way at random).
int own_slot() { return 1000 + int(::getpid() % 30000); }

SealedTest run_fixture(const std::string& name) {
  test::TempFolder scratch("pt-sandbox-test");
  Sandbox sandbox = Sandbox::standard((scratch.path() / "scratch").string(), own_slot());
  return run_sealed_test(kFixture, name, sandbox, 30.0);
}

TEST(GraderSandbox, APassingTestPassesAndAFailingOneFails) {
  SealedTest pass = run_fixture("Fixture.Passes");
  EXPECT_EQ(pass.status, SealedStatus::passed) << pass.why << "\n" << pass.output;
  SealedTest fail = run_fixture("Fixture.Fails");
  EXPECT_EQ(fail.status, SealedStatus::failed);
  SealedTest crash = run_fixture("Fixture.Crashes");
  EXPECT_EQ(crash.status, SealedStatus::failed);
  EXPECT_NE(crash.why.find("SIGABRT"), std::string::npos) << crash.why;
}

TEST(GraderSandbox, ExitZeroInsideATestFails) {
  for (const char* name : {"Fixture.ExitsZero", "Fixture.QuickExitsZero"}) {
    SealedTest t = run_fixture(name);
    EXPECT_EQ(t.status, SealedStatus::failed) << name;
    EXPECT_NE(t.why.find("ended before it finished"), std::string::npos) << t.why;
  }
}

TEST(GraderSandbox, PrintedPassAndSkipLinesCountForNothing) {
  SealedTest t = run_fixture("Fixture.PrintsFakePassAndSkipLines");
  EXPECT_EQ(t.status, SealedStatus::failed);
  EXPECT_NE(t.output.find("[       OK ]"), std::string::npos) << "it did print them";
}

TEST(GraderSandbox, AForgedReportLineFailsTheTest) {
  SealedTest t = run_fixture("Fixture.ForgesReportLines");
  EXPECT_EQ(t.status, SealedStatus::failed);
  EXPECT_NE(t.why.find("did not write"), std::string::npos) << t.why;
}

TEST(GraderSandbox, ASkipIsReportedAsOne) {
  EXPECT_EQ(run_fixture("Fixture.Skips").status, SealedStatus::skipped);
  // A name the executable does not have is a failure, not a skip.
  EXPECT_EQ(run_fixture("Fixture.NoSuchTest").status, SealedStatus::failed);
}

TEST(GraderSandbox, TheReportIsJudgedLineByLine) {
  ChildResult clean;
  clean.exit_code = 0;
  const std::string n = "abc123";
  std::string why;
  EXPECT_EQ(judge_sealed_report("PTREPORT abc123 test S.T passed\nPTREPORT abc123 end 1\n", n,
                                "S.T", clean, &why),
            SealedStatus::passed);
  // No closing line: the program did not end normally.
  EXPECT_EQ(judge_sealed_report("PTREPORT abc123 test S.T passed\n", n, "S.T", clean, &why),
            SealedStatus::failed);
  // A pass with a non-zero exit, two verdicts, another test's line, a wrong nonce.
  ChildResult bad = clean;
  bad.exit_code = 1;
  EXPECT_EQ(judge_sealed_report("PTREPORT abc123 test S.T passed\nPTREPORT abc123 end 1\n", n,
                                "S.T", bad, &why),
            SealedStatus::failed);
  EXPECT_EQ(judge_sealed_report("PTREPORT abc123 test S.T failed\nPTREPORT abc123 test S.T passed\n"
                                "PTREPORT abc123 end 1\n", n, "S.T", clean, &why),
            SealedStatus::failed);
  EXPECT_EQ(judge_sealed_report("PTREPORT abc123 test S.U passed\nPTREPORT abc123 test S.T passed\n"
                                "PTREPORT abc123 end 1\n", n, "S.T", clean, &why),
            SealedStatus::failed);
  EXPECT_EQ(judge_sealed_report("PTREPORT abc124 test S.T passed\nPTREPORT abc124 end 1\n", n,
                                "S.T", clean, &why),
            SealedStatus::failed);
  EXPECT_EQ(draw_nonce().size(), 32u);
  EXPECT_NE(draw_nonce(), draw_nonce());
}

TEST(GraderSandbox, TheFixturesTestsAreListed) {
  std::vector<std::string> names = list_gtest_tests(kFixture, 30.0);
  EXPECT_EQ(names.size(), 8u);
  EXPECT_EQ(names.front(), "Fixture.Passes");
}

TEST(GraderSandbox, ARenderFileMustBeTheRendersOwn) {
  test::TempFolder dir("pt-sandbox-output");
  Sandbox unprotected;
  std::filesystem::path real = dir.write("real.exr", "x");
  EXPECT_EQ(check_scratch_output(real.string(), unprotected), "");
  std::filesystem::path link = dir.path() / "link.exr";
  std::filesystem::create_symlink(real, link);
  EXPECT_NE(check_scratch_output(link.string(), unprotected).find("symbolic link"),
            std::string::npos);
  std::filesystem::path hard = dir.path() / "hard.exr";
  std::filesystem::create_hard_link(real, hard);
  EXPECT_NE(check_scratch_output(hard.string(), unprotected).find("hard link"), std::string::npos);
  EXPECT_NE(check_scratch_output((dir.path() / "none.exr").string(), unprotected), "");
}

TEST(GraderSandbox, AsRootTheStudentsUserCannotReadTheGradersFiles) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root to switch users";
  test::TempFolder dir("pt-sandbox-user");
  std::filesystem::path secret = dir.write("manifest.json", "{\"crc32\": \"secret\"}");
  std::filesystem::permissions(secret, std::filesystem::perms(0600));
  Sandbox sandbox = Sandbox::standard((dir.path() / "scratch").string(), own_slot());
  ASSERT_TRUE(sandbox.protects());
  std::string scratch = sandbox.make_scratch("read");
  ChildResult r = run_child({"cat", secret.string()}, sandbox.options(scratch, 10.0));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.output.find("secret"), std::string::npos);
  ChildResult w = run_child({"sh", "-c", "echo x > " + (dir.path() / "outside").string()},
                            sandbox.options(scratch, 10.0));
  EXPECT_FALSE(w.ok());
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "outside"));
  ChildResult inside = run_child({"sh", "-c", "echo x > mine && cat mine"},
                                 sandbox.options(scratch, 10.0));
  EXPECT_TRUE(inside.ok()) << inside.describe() << inside.output;
}

}  // namespace
}  // namespace pt::grader
