// The handout's stripping of solution blocks.
#include "grader/handout.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"

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
  // Wherever the marker stands: a sixth line (app/accel/sheared_triangle_test.cpp's once leaked
  // into the handout), the last line, a CMake or patch file's own comment leader.
  EXPECT_TRUE(is_solution_only("1\n2\n3\n4\n5\n// SOLUTION-ONLY FILE: the wide BVH\n"));
  std::string long_file(200, '\n');
  EXPECT_TRUE(is_solution_only(long_file + "  /// SOLUTION-ONLY FILE\n"));
  EXPECT_TRUE(is_solution_only("# the build\n# SOLUTION-ONLY FILE: not handed out\n"));
  EXPECT_TRUE(is_solution_only("SOLUTION-ONLY FILE: mutant 01 of the complete solution\n"));
  // A line that only mentions the marker is none.
  EXPECT_FALSE(is_solution_only("/// A file that says \"SOLUTION-ONLY FILE\" is not handed out.\n"));
  EXPECT_FALSE(is_solution_only("if (line.find(\"SOLUTION-ONLY FILE\") != npos) return true;\n"));
}

// Every file of the tree that carries the marker on any line is recognised, and the file that
// once leaked (its marker on line 6) is one of them.
TEST(GraderHandout, EveryMarkedFileOfTheTreeIsSolutionOnly) {
  const std::filesystem::path source = test::source_dir();
  int marked = 0;
  for (const std::string& rel : tracked_files(source.string())) {
    std::ifstream in(source / rel, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    bool marker_line = false;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      size_t at = line.find("SOLUTION-ONLY FILE");
      if (at != std::string::npos && line.find_first_not_of(" \t/#*;-") == at) marker_line = true;
    }
    if (!marker_line) continue;
    ++marked;
    EXPECT_TRUE(is_solution_only(text)) << rel;
  }
  EXPECT_GT(marked, 20);
  EXPECT_TRUE(is_solution_only(
      [&] {
        std::ifstream in(source / "app/accel/sheared_triangle_test.cpp", std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), {});
      }()));
}

// The stub lines the bundle may quote are the handout's stubs' own: the camera function's stub
// gives one, its file and the line of its PT_STUDENT_TODO, in the form the stub prints
// (PT_STUDENT_TODO_FORMAT, the one definition both use).
TEST(GraderHandout, StubMessagesAreWhatTheStubsPrint) {
  test::TempFolder dir("pt-stub-messages");
  const std::string rel = "parts/1-raygen/camera_ray.cpp";
  const std::filesystem::path source = test::source_dir();
  std::ifstream in(source / rel, std::ios::binary);
  std::string stub = strip_solution(std::string((std::istreambuf_iterator<char>(in)), {}), rel);
  std::filesystem::create_directories(dir.path() / "parts/1-raygen");
  std::ofstream(dir.path() / rel) << stub;
  std::set<std::string> messages = stub_messages(dir.path(), {rel});
  ASSERT_EQ(messages.size(), 1u);
  const std::string& m = *messages.begin();
  EXPECT_EQ(m.rfind("part 1 not implemented: generate_camera_ray at parts/1-raygen/camera_ray.cpp:", 0), 0u) << m;
  EXPECT_NE(m.find("(see the STUDENT comment there)"), std::string::npos) << m;
  // The line number is the stub's own line of PT_STUDENT_TODO.
  std::istringstream lines(stub);
  int number = 0, at = 0;
  for (std::string line; std::getline(lines, line);)
    if (++number && line.find("PT_STUDENT_TODO(") != std::string::npos) at = number;
  EXPECT_NE(m.find(":" + std::to_string(at) + " "), std::string::npos) << m;
}

}  // namespace
}  // namespace pt::grader
