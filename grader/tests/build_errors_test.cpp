// What the results say of a failed build: where its first errors are and what kind, never the
// compiler's words. A file made to carry text out (a #line naming any file at any line, an #error,
// a static_assert's message, a long identifier) is compiled by the real compiler, and none of that
// text, nor a line or column past its bound, reaches the excerpt.
#include "grader/build_errors.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"
#include "grader/process/child_process.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

const std::string kPayload = "PAYLOADxq7";

TEST(GraderBuildErrors, NoTextTheCodeChoseReachesTheExcerpt) {
  test::TempFolder dir("pt-build-errors");
  fs::create_directories(dir.path() / "parts" / "1-raygen");
  const fs::path file = dir.path() / "parts" / "1-raygen" / "sphere_intersect.cpp";
  std::ofstream(file) << "int a = " << kPayload << "_identifier_" << std::string(300, 'z') << ";\n"
                      << "static_assert(sizeof(int) == 3, \"" << kPayload << " in a message\");\n"
                      << "#line 1234567 \"" << kPayload << "_file.cpp\"\n"
                      << "int b = " << kPayload << "_after_line;\n"
                      << "#error " << kPayload << " in an #error\n";
  ChildResult c = run_child({"c++", "-std=c++17", "-c", file.string(), "-o",
                             (dir.path() / "x.o").string()}, 120.0);
  if (!c.started) GTEST_SKIP() << "no c++ compiler on this machine";
  ASSERT_FALSE(c.ok()) << c.output;
  ASSERT_NE(c.output.find(kPayload), std::string::npos) << "the compiler quotes the code: " << c.output;
  const std::string said = build_errors(c.output, dir.path().string());
  EXPECT_EQ(said.find(kPayload), std::string::npos) << said;
  EXPECT_EQ(said.find("1234567"), std::string::npos) << said;
  EXPECT_NE(said.find("parts/1-raygen/sphere_intersect.cpp:1:"), std::string::npos) << said;
  EXPECT_NE(said.find("errors in all"), std::string::npos) << said;
  EXPECT_LE(said.size(), 400u) << said;
}

TEST(GraderBuildErrors, EachErrorIsAFileOfTheProjectALineAndAKind) {
  test::TempFolder dir("pt-build-errors");
  fs::create_directories(dir.path() / "parts");
  std::ofstream(dir.path() / "parts" / "a.cpp") << "\n";
  const std::string root = dir.path().string();
  const std::string output =
      root + "/parts/a.cpp:12:5: error: 'x' was not declared in this scope\n" +
      "elsewhere/" + kPayload + ".cpp:3:1: error: #error " + kPayload + "\n" +
      root + "/parts/a.cpp:4:2: fatal error: " + kPayload + ".h: No such file or directory\n" +
      "/usr/bin/ld: a.o: in function `f': undefined reference to `" + kPayload + "()'\n";
  const std::string said = build_errors(output, root);
  EXPECT_NE(said.find("parts/a.cpp:12:5: a name that is not declared"), std::string::npos) << said;
  EXPECT_NE(said.find("a file:3:1: an #error directive"), std::string::npos) << said;
  EXPECT_EQ(said.find("No such file"), std::string::npos) << said;  // past the first two
  EXPECT_NE(said.find("4 errors in all"), std::string::npos) << said;
  EXPECT_EQ(said.find(kPayload), std::string::npos) << said;
}

// An #include that __has_include found but the student's user may not read: the compiler's
// error has no line, and its kind is what the bundle's read_solution cheater is told.
TEST(GraderBuildErrors, AnErrorOfNoLineIsTheCompilersAndNamesNoFile) {
  const std::string said = build_errors(
      "cc1plus: fatal error: ../../" + kPayload + "/sphere_intersect.cpp: Permission denied\n"
      "compilation terminated.\n", "/nowhere");
  EXPECT_NE(said.find("the compiler: an #include of a file it may not read (Permission denied)"),
            std::string::npos) << said;
  EXPECT_EQ(said.find(kPayload), std::string::npos) << said;
}

TEST(GraderBuildErrors, ALinkErrorNamesNoSymbol) {
  const std::string said =
      build_errors("/usr/bin/ld: x.o: in function `main':\nx.cpp:(.text+0x5): undefined reference "
                   "to `" + kPayload + "()'\ncollect2: error: ld returned 1 exit status\n", "/nowhere");
  EXPECT_NE(said.find("the link: a function declared and called but never defined"), std::string::npos) << said;
  EXPECT_EQ(said.find(kPayload), std::string::npos) << said;
  EXPECT_EQ(said.find("errors in all"), std::string::npos) << "collect2's line is no error of its own: " << said;
}

}  // namespace
}  // namespace pt::grader
