// The handout's stripping of solution blocks.
#include "grader/handout.h"

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

TEST(GraderHandout, SolutionBlocksGoAndStubsStay) {
  std::string code =
      "int f(int x) {\n"
      "  // BEGIN SOLUTION\n"
      "  return x * 2;\n"
      "  // END SOLUTION\n"
      "  // STUDENT: double x\n"
      "  PT_STUDENT_TODO(\"part 1\", \"f\");\n"
      "  return 0;\n"
      "}\n";
  int blocks = 0;
  std::string out = strip_solution(code, "f.cpp", &blocks);
  EXPECT_EQ(blocks, 1);
  EXPECT_EQ(out.find("x * 2"), std::string::npos) << out;
  EXPECT_EQ(out.find("SOLUTION"), std::string::npos) << out;
  EXPECT_NE(out.find("// STUDENT: double x"), std::string::npos) << out;
  EXPECT_NE(out.find("PT_STUDENT_TODO"), std::string::npos) << out;
  EXPECT_EQ(strip_solution("no markers\n", "g.cpp"), "no markers\n");
}

TEST(GraderHandout, PackageListKeepsTheStudentsLines) {
  std::string list =
      "# comment: every set-up\n"
      "\n"
      "cmake            all                the build\n"
      "libcmark-dev     student,developer  the write-up\n"
      "zip              developer          the bundle\n"
      "zipinfo          students,grading   a set-up named like the student's is not it\n";
  std::string out = student_package_list(list);
  EXPECT_EQ(out,
            "# comment: every set-up\n"
            "\n"
            "cmake            all                the build\n"
            "libcmark-dev     student,developer  the write-up\n");
}

TEST(GraderHandout, UnbalancedMarkersNameFileAndLine) {
  EXPECT_THROW(strip_solution("a\n// BEGIN SOLUTION\nb\n", "p.cpp"), std::runtime_error);
  try {
    strip_solution("a\n// END SOLUTION\n", "p.cpp");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("p.cpp:2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(strip_solution("// BEGIN SOLUTION\n// BEGIN SOLUTION\n// END SOLUTION\n", "q.h"),
               std::runtime_error);
}

TEST(GraderHandout, SolutionOnlyFilesAreRecognised) {
  EXPECT_TRUE(is_solution_only("// Checks the solution.\n// SOLUTION-ONLY FILE\nint x;\n"));
  EXPECT_FALSE(is_solution_only("// ordinary\nint x;\n"));
  EXPECT_FALSE(is_solution_only("1\n2\n3\n4\n5\n6\n// SOLUTION-ONLY FILE\n"));
}

}  // namespace
}  // namespace pt::grader
