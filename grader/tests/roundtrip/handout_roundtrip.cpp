// The handout round trip: make the handout, build it from scratch, grade its Part 1. It must
// build, and its grader must give 0 points with "not implemented" and a non-zero exit, without
// crashing. A full CMake build: minutes, so it has its own long time limit.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/process/child_process.h"
#include "grader/report.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

TEST(GraderHandoutRoundTrip, HandoutBuildsAndGradesPart1AsZero) {
  fs::path root = fs::temp_directory_path() / ("pt-handout-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::path handout = root / "handout", build = root / "build";

  ChildResult made = run_child({GRADER_EXE, "--source", PT_SOURCE_DIR, "handout", handout.string()}, 120);
  ASSERT_TRUE(made.ok()) << made.describe() << "\n" << made.output;
  // No solution left anywhere in the handout.
  ChildResult grep = run_child({"grep", "-rl", "BEGIN SOLUTION", (handout / "parts").string()}, 60);
  EXPECT_EQ(grep.exit_code, 1) << "solution markers left in: " << grep.output;
  // Nor the app's wide BVH, whose files are marked solution-only (they hold a complete triangle
  // test and traversal): the handout's renders trace the student's own tree.
  EXPECT_FALSE(fs::exists(handout / "app" / "accel" / "wide_bvh.cpp"));
  EXPECT_FALSE(fs::exists(handout / "app" / "accel" / "sheared_triangle.h"));
  // The given code the parts sit on is handed out whole.
  EXPECT_TRUE(fs::exists(handout / "pipeline" / "2-bvh" / "bvh_build.cpp"));

  ChildResult configure = run_child({"cmake", "-S", handout.string(), "-B", build.string(),
                                     "-DCMAKE_BUILD_TYPE=Debug"}, 300);
  ASSERT_TRUE(configure.ok()) << configure.describe() << "\n" << configure.output;
  ChildResult compile = run_child({"cmake", "--build", build.string(), "--target", "grader",
                                   "grade_part1", "-j2"}, 2000, {}, 4 << 20);
  ASSERT_TRUE(compile.ok()) << "the handout does not build: " << compile.describe() << "\n"
                            << compile.output.substr(compile.output.size() > 6000 ? compile.output.size() - 6000 : 0);

  fs::path json = root / "results.json";
  ChildResult graded = run_child({(build / "grader" / "grader").string(), "--part", "1", "--out",
                                  (root / "out").string(), "--json", json.string()}, 600);
  EXPECT_TRUE(graded.started);
  EXPECT_FALSE(graded.timed_out);
  EXPECT_EQ(graded.signal, 0) << graded.describe();
  EXPECT_EQ(graded.exit_code, 1) << graded.output;
  EXPECT_NE(graded.output.find("Total: 0/"), std::string::npos) << graded.output;
  EXPECT_NE(graded.output.find("not implemented"), std::string::npos) << graded.output;
  std::ifstream in(json);
  nlohmann::json results = nlohmann::json::parse(in, nullptr, false);
  EXPECT_EQ(validate_gradescope(results), "") << results.dump(2);
  EXPECT_EQ(results.value("score", -1.0), 0.0);
  fs::remove_all(root);
}

}  // namespace
}  // namespace pt::grader
