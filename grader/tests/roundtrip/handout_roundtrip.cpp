// The handout round trip: make the handout, build it from scratch, grade every part. It must
// build; its README must be the student's; it must hold none of the answers the instructor's
// tree keeps in its test helpers; its grader must refuse --make-reference, warn when --no-build
// would grade stale binaries, and give every step of every part 0 points without crashing, with
// each stub's "not implemented" line naming its file (relative to the project) and line. A full
// CMake build: minutes, so it has its own long time limit.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <cstdio>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grader/process/child_process.h"
#include "framework/testing/test_paths.h"
#include "framework/text/text_file.h"
#include "grader/report.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

std::string tail(const std::string& s, size_t n = 6000) {
  return s.substr(s.size() > n ? s.size() - n : 0);
}

/// The handout's README is the student's, and every relative link in it resolves in the handout.
void expect_students_readme(const fs::path& handout) {
  const std::string readme = read_text_file(handout / "README.md");
  EXPECT_NE(readme.find("# The path tracer: your handout"), std::string::npos) << readme.substr(0, 300);
  for (const char* word : {"BEGIN SOLUTION", "--make-reference", "SOLUTION-ONLY"})
    EXPECT_EQ(readme.find(word), std::string::npos) << "the handout's README mentions " << word;
  const std::regex link(R"(\]\(([^)#:]+)(#[^)]*)?\))");
  int links = 0;
  for (std::sregex_iterator it(readme.begin(), readme.end(), link), end; it != end; ++it, ++links)
    EXPECT_TRUE(fs::exists(handout / (*it)[1].str())) << "README.md links to " << (*it)[1];
  EXPECT_GT(links, 30);
}

/// The exact references some checks need are not handed out in a form that answers a step.
void expect_no_answers_in_helpers(const fs::path& handout) {
  struct Banned {
    const char* file;
    const char* text;
    const char* what;
  };
  for (const Banned& b : std::initializer_list<Banned>{
           {"framework/testing/test_scenes.h", "pv = glm::cross(d, e2)", "a Möller–Trumbore test"},
           {"framework/testing/test_scenes.h", "copysign", "the stable sphere quadratic"},
           {"framework/testing/double_query.cpp", "copysign", "the stable sphere quadratic"},
           {"parts/2-bvh/tests/bvh_check.h", "(lo_[i][a] - o) / d", "a slab test"},
           {"parts/1-raygen/tests/step4_sphere_test.cpp", "copysign", "the stable sphere quadratic"}}) {
    const fs::path p = handout / b.file;
    ASSERT_TRUE(fs::exists(p)) << b.file;
    EXPECT_EQ(read_text_file(p).find(b.text), std::string::npos) << b.file << " holds " << b.what;
  }
}

TEST(GraderHandoutRoundTrip, HandoutBuildsAndGradesEveryStepAsZero) {
  fs::path root = fs::temp_directory_path() / ("pt-handout-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::path handout = root / "handout", build = handout / "build";

  ChildResult made = run_child({GRADER_EXE, "--source", pt::test::source_dir(), "handout", handout.string()}, 120);
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
  expect_students_readme(handout);
  expect_no_answers_in_helpers(handout);

  // Built as a student builds it, with the handout's own build script (Release, a compiler cache
  // where the machine has one, keyed relative to the project): the handout's files that equal the
  // instructor's (the framework, the given code, the tests) come back from the cache this tree's
  // build filled, so the round trip costs the stubs and the links, not a second full build.
  ChildOptions build_options;
  build_options.limits.wall_seconds = 2400;
  build_options.limits.max_output = 4 << 20;
  build_options.environment = {"BUILD_DIR=build", "JOBS=2"};
  ChildResult compile = run_child({"bash", (handout / "tools" / "build.sh").string(), "--target", "grader",
                                   "grade_part1", "grade_part2", "grade_part3", "grade_part4",
                                   "grade_part5"}, build_options);
  ASSERT_TRUE(compile.ok()) << "the handout does not build: " << compile.describe() << "\n"
                            << tail(compile.output);
  std::printf("the handout built in %.0f s\n", compile.seconds);
  const std::string grader = (build / "grader" / "grader").string();

  // The references are the instructor's to make, from the complete solution the handout lacks.
  ChildResult remake = run_child({grader, "--make-reference", "--part", "3"}, 60);
  EXPECT_EQ(remake.exit_code, 2) << remake.output;
  EXPECT_NE(remake.output.find("--make-reference is the instructor's"), std::string::npos) << remake.output;

  fs::path json = root / "results.json";
  ChildResult graded = run_child({grader, "--all", "--out", (root / "out").string(), "--json",
                                  json.string()}, 2400, {}, 4 << 20);
  EXPECT_TRUE(graded.started);
  EXPECT_FALSE(graded.timed_out);
  EXPECT_EQ(graded.signal, 0) << graded.describe();
  EXPECT_EQ(graded.exit_code, 1) << tail(graded.output);
  EXPECT_NE(graded.output.find("Total: 0/"), std::string::npos) << tail(graded.output);
  std::ifstream in(json);
  nlohmann::json results = nlohmann::json::parse(in, nullptr, false);
  EXPECT_EQ(validate_gradescope(results), "") << results.dump(2);
  EXPECT_EQ(results.value("score", -1.0), 0.0);
  // Every graded unit (a step, once the rubric is by step) of every part at 0 points, and every
  // part present.
  std::set<int> parts;
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array())) {
    EXPECT_EQ(t.value("score", -1.0), 0.0) << t.value("name", "?") << " scores on the stubs:\n"
                                           << t.value("output", "");
    std::smatch m;
    const std::string name = t.value("name", "");
    if (std::regex_search(name, m, std::regex(R"(^part(\d))"))) parts.insert(std::stoi(m[1]));
  }
  EXPECT_EQ(parts, (std::set<int>{1, 2, 3, 4, 5})) << results.dump(2);

  // Each stub's warning names its file, relative to the project, and the line of its
  // PT_STUDENT_TODO; together they name a stub in every part.
  const std::regex todo(R"(part (\d) not implemented: (\S+) at ([^ :]+):(\d+))");
  std::set<int> warned;
  int lines = 0;
  for (std::sregex_iterator it(graded.output.begin(), graded.output.end(), todo), end; it != end; ++it, ++lines) {
    const std::string file = (*it)[3];
    const int line = std::stoi((*it)[4]);
    warned.insert(std::stoi((*it)[1]));
    EXPECT_EQ(file.rfind("parts/", 0), 0u) << "not relative to the project: " << file;
    std::ifstream src(handout / file);
    ASSERT_TRUE(src) << file << " is not in the handout";
    std::string text;
    for (int i = 0; i < line && std::getline(src, text);) ++i;
    EXPECT_NE(text.find("PT_STUDENT_TODO"), std::string::npos)
        << file << ":" << line << " is not the stub of " << (*it)[2] << ": " << text;
  }
  EXPECT_GT(lines, 0) << tail(graded.output);
  EXPECT_EQ(warned, (std::set<int>{1, 2, 3, 4, 5})) << tail(graded.output);

  // --no-build grades the binaries as they are, and says so when a source is newer.
  const fs::path edited = handout / "parts" / "1-raygen" / "camera_ray.cpp";
  fs::last_write_time(edited, fs::file_time_type::clock::now() + std::chrono::seconds(5));
  ChildResult stale = run_child({grader, "--part", "1", "--no-build", "--no-tests", "--out",
                                 (root / "out").string()}, 600);
  EXPECT_NE(stale.output.find("warning: --no-build"), std::string::npos) << tail(stale.output);
  EXPECT_NE(stale.output.find("parts/1-raygen/camera_ray.cpp"), std::string::npos) << tail(stale.output);
  if (HasFailure())
    std::printf("the handout, its build and the grader's output are kept in %s\n", root.c_str());
  else
    fs::remove_all(root);
}

}  // namespace
}  // namespace pt::grader
