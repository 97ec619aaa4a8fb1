// What the handout tool and the grader do for the handout's sake: the student's README at the
// handout's root with its links rebased, a tree without the solution recognised (so
// --make-reference is refused there), and --no-build's stale-binary warning.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "framework/testing/temp_folder.h"
#include "grader/handout_guard.h"
#include "grader/handout_readme.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

TEST(GraderHandoutReadme, LinksAreRebasedFromDocsHandoutToTheRoot) {
  const std::string md =
      "[Part 1](part1.md) [code](../../parts/1-raygen/camera_ray.cpp) [layers](../architecture.md#x)\n"
      "[web](https://example.org) [here](#grading) `[code span](part1.md)`\n"
      "```\n[fenced](part1.md)\n```\n";
  const std::string out = rebase_links(md, "docs/handout/README.md", "README.md");
  EXPECT_NE(out.find("[Part 1](docs/handout/part1.md)"), std::string::npos) << out;
  EXPECT_NE(out.find("[code](parts/1-raygen/camera_ray.cpp)"), std::string::npos) << out;
  EXPECT_NE(out.find("[layers](docs/architecture.md#x)"), std::string::npos) << out;
  EXPECT_NE(out.find("[web](https://example.org)"), std::string::npos) << out;
  EXPECT_NE(out.find("[here](#grading)"), std::string::npos) << out;
  EXPECT_NE(out.find("`[code span](part1.md)`"), std::string::npos) << out;
  EXPECT_NE(out.find("[fenced](part1.md)"), std::string::npos) << out;
}

TEST(GraderHandoutReadme, TheStudentsReadmeReplacesTheInstructors) {
  test::TempFolder tmp;
  tmp.write("src/docs/handout/README.md", "# Start here\n[Part 1](part1.md)\n");
  fs::create_directories(tmp.path() / "out");
  write_student_readme((tmp.path() / "src").string(), (tmp.path() / "out").string());
  std::ifstream in(tmp.path() / "out" / "README.md");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(text, "# Start here\n[Part 1](docs/handout/part1.md)\n");
  EXPECT_THROW(write_student_readme((tmp.path() / "none").string(), (tmp.path() / "out").string()),
               std::runtime_error);
}

TEST(GraderHandoutGuard, ATreeWithoutSolutionBlocksIsAHandout) {
  test::TempFolder tmp;
  tmp.write("parts/1-raygen/a.cpp", "int f() {\n  // STUDENT: write f\n  return 0;\n}\n");
  EXPECT_FALSE(has_solution(tmp.path().string()));
  tmp.write("parts/1-raygen/b.cpp", "int g() {\n  // BEGIN SOLUTION\n  return 1;\n  // END SOLUTION\n}\n");
  EXPECT_TRUE(has_solution(tmp.path().string()));
}

TEST(GraderHandoutGuard, NoBuildWarnsOfSourcesNewerThanTheBinaries) {
  test::TempFolder tmp;
  const fs::path old_source = tmp.write("parts/1-raygen/a.cpp", "int f();\n");
  const fs::path other = tmp.write("framework/math/b.h", "int g();\n");
  const fs::path binary = tmp.write("build/app/pathtracer", "binary");
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(old_source, now - std::chrono::hours(2));
  fs::last_write_time(other, now - std::chrono::hours(2));
  fs::last_write_time(binary, now - std::chrono::hours(1));
  EXPECT_TRUE(sources_newer_than(tmp.path().string(), {binary.string()}).empty());
  EXPECT_EQ(stale_warning({}), "");

  fs::last_write_time(old_source, now);  // edited after the build
  const std::vector<std::string> stale = sources_newer_than(tmp.path().string(), {binary.string()});
  ASSERT_EQ(stale, std::vector<std::string>{"parts/1-raygen/a.cpp"});
  const std::string warning = stale_warning(stale);
  EXPECT_NE(warning.find("parts/1-raygen/a.cpp"), std::string::npos) << warning;
  EXPECT_NE(warning.find("--no-build"), std::string::npos) << warning;
  // A binary that was never built is older than everything.
  EXPECT_EQ(sources_newer_than(tmp.path().string(), {(tmp.path() / "missing").string()}).size(), 2u);
}

}  // namespace
}  // namespace pt::grader
