// Grading renders through a stand-in renderer: a good render passes, one that crashes, hangs
// or writes garbage fails alone, and a reference that does not match its checksum is refused.
#include "framework/testing/test_paths.h"
#include "grader/grade.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "framework/image/estimate_exr.h"
#include "grader/report.h"
#include "grader/tests/synthetic.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

/// A project in a temporary folder: a manifest, references, and a fake `pathtracer` script
/// whose behaviour the scene's name chooses (the scene file of "good" is the render itself).
class GraderGrade : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("pt-grader-grade-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "reference");
    fs::create_directories(root_ / "scenes");
    write_estimate_exr((root_ / "reference" / "ref.exr").string(), testing::full_render(64, 1));
    write_estimate_exr((root_ / "scenes" / "good.exr").string(), testing::full_render(16, 2));
    fs::copy_file(root_ / "scenes" / "good.exr", root_ / "scenes" / "stub.exr");
    write_estimate_exr((root_ / "scenes" / "dark.exr").string(),
                       testing::full_render(64, 3, 0.95f));
    for (const char* s : {"crash", "hang", "garbage"}) std::ofstream(root_ / "scenes" / s) << "x";
    fs::path script = root_ / "fake-pathtracer";
    std::ofstream(script) << "#!/bin/sh\n"
                             "while [ $# -gt 1 ]; do [ \"$1\" = -f ] && out=$2; shift; done\n"
                             "case \"$1\" in\n"
                             "  *crash) kill -SEGV $$ ;;\n"
                             "  *hang) sleep 60 ;;\n"
                             "  *garbage) echo garbage > \"$out\" ;;\n"
                             "  *stub.exr) echo 'part 3 not implemented: f at parts/f.cpp:1' >&2;"
                             " cp \"$1\" \"$out\" ;;\n"
                             "  *) cp \"$1\" \"$out\" ;;\n"
                             "esac\n";
    fs::permissions(script, fs::perms::owner_all);
    std::string sum = file_checksum((root_ / "reference" / "ref.exr").string());
    nlohmann::ordered_json m;
    m["block_size"] = 16;
    m["alpha"] = 0.01;
    // One step per render, so that each failure shows in a step of its own.
    nlohmann::ordered_json part = {{"part", 3}, {"steps", nlohmann::ordered_json::array()}};
    int step = 0;
    for (const char* s : {"good.exr", "crash", "hang", "garbage", "dark.exr"}) {
      nlohmann::ordered_json render = {{"name", s},
                                       {"scene", std::string("scenes/") + s},
                                       {"kind", "direct"},
                                       {"args", {"-s", "16"}},
                                       {"reference_args", {"-s", "64"}},
                                       {"seed", 2},
                                       {"reference_seed", 1},
                                       {"timeout", 1.0},
                                       {"reference", "reference/ref.exr"},
                                       {"made", {{"crc32", sum}}}};
      part["steps"].push_back({{"step", ++step},
                               {"name", std::string("s") + std::to_string(step)},
                               {"points", 5},
                               {"renders", nlohmann::ordered_json::array({render})}});
    }
    m["parts"] = {part};
    std::ofstream(root_ / "reference" / "manifest.json") << m.dump(2);
    options_.source_dir = root_.string();
    options_.manifest_path = (root_ / "reference" / "manifest.json").string();
    options_.pathtracer = script.string();
    options_.out_dir = (root_ / "out").string();
    options_.build = false;
    options_.run_tests = false;
  }
  void TearDown() override { fs::remove_all(root_); }

  /// Records of manifest `m`'s Parts 1 and 2 (one step each): Part 1 passed, Part 2 failed.
  void record_part1_passing_part2_failing(const Manifest& m) {
    PartResult one;
    one.part = 1;
    one.steps.push_back(score_step(m.parts[0].steps[0],
                                   {CheckResult{"part1.step1.a.x", "test", true, false, "", 0.0, 0}}));
    PartResult two;
    two.part = 2;
    two.steps.push_back(score_step(
        m.parts[1].steps[0], {CheckResult{"part2.step1.b.x", "test", false, false, "failed", 0.0, 0}}));
    record_state(one, options_);
    record_state(two, options_);
  }

  fs::path root_;
  GradeOptions options_;
};

TEST_F(GraderGrade, EachFailureStaysInItsOwnStep) {
  Manifest m = read_manifest(options_.manifest_path);
  PartResult p = grade_part(m, 3, options_);
  ASSERT_EQ(p.steps.size(), 5u);
  const std::vector<StepResult>& r = p.steps;
  EXPECT_TRUE(r[0].passed()) << r[0].message;
  EXPECT_EQ(r[0].score, 5.0);
  EXPECT_EQ(r[0].name, "part3.step1.s1");
  EXPECT_EQ(r[0].checks[0].name, "part3.step1.render.good.exr");
  EXPECT_FALSE(r[1].passed());
  EXPECT_NE(r[1].message.find("crashed (SIGSEGV"), std::string::npos) << r[1].message;
  EXPECT_FALSE(r[2].passed());
  EXPECT_NE(r[2].message.find("time limit"), std::string::npos) << r[2].message;
  EXPECT_LT(r[2].checks[0].seconds, 10.0);
  EXPECT_FALSE(r[3].passed());
  EXPECT_NE(r[3].message.find("cannot be read"), std::string::npos) << r[3].message;
  EXPECT_FALSE(r[4].passed());
  EXPECT_NE(r[4].message.find("slightly too dark everywhere"), std::string::npos) << r[4].message;
  EXPECT_NE(r[4].message.find("part3.step5.render.dark.exr_diff.png"), std::string::npos) << r[4].message;
  EXPECT_TRUE(fs::exists(root_ / "out" / "part3.step5.render.dark.exr_diff.png"));
  std::ostringstream table;
  print_score_table(table, {p});
  EXPECT_NE(table.str().find("Total: 5/25"), std::string::npos) << table.str();
  EXPECT_EQ(validate_gradescope(gradescope_results({p}, RunInfo{})), "");
}

TEST_F(GraderGrade, ARenderThroughThisPartsStubsEarnsNothing) {
  // The right image, made by a renderer that says it ran one of this part's stubs (Part 2's walk
  // every leaf and so give correct images when Part 1 is the solution's): not the student's work.
  nlohmann::ordered_json m;
  std::ifstream(options_.manifest_path) >> m;
  m["parts"][0]["steps"][0]["renders"][0]["scene"] = "scenes/stub.exr";
  std::ofstream(options_.manifest_path) << m.dump(2);
  PartResult p = grade_part(read_manifest(options_.manifest_path), 3, options_);
  EXPECT_FALSE(p.steps[0].passed());
  EXPECT_NE(p.steps[0].message.find("unwritten stubs"), std::string::npos) << p.steps[0].message;
  EXPECT_NE(p.steps[0].message.find("parts/f.cpp:1"), std::string::npos) << p.steps[0].message;
}

// A render of a course scene that is not beside the project is a skip that says what to do, and
// costs nothing; where the bundle grades (it ships the scenes) it is the grader's own error.
TEST_F(GraderGrade, AMissingCourseSceneIsASkipLocallyAndAnErrorInTheBundle) {
  nlohmann::ordered_json m;
  std::ifstream(options_.manifest_path) >> m;
  nlohmann::ordered_json course = m["parts"][0]["steps"][0]["renders"][0];
  course["name"] = "course";
  course["scene"] = "no_such_dir/absent.dae";
  course["course_scene"] = true;
  m["parts"][0]["steps"][0]["renders"].push_back(course);
  std::ofstream(options_.manifest_path) << m.dump(2);
  const Manifest manifest = read_manifest(options_.manifest_path);
  PartResult p = grade_part(manifest, 3, options_);
  const StepResult& st = p.steps[0];
  ASSERT_EQ(st.checks.size(), 2u);
  EXPECT_TRUE(st.checks[1].skipped);
  EXPECT_TRUE(st.passed()) << st.message;
  EXPECT_EQ(st.score, 5.0);
  EXPECT_NE(st.message.find("put the course's scenes at ../shared/scenes/cs184"), std::string::npos)
      << st.message;
  EXPECT_DOUBLE_EQ(p.skipped_points(), 2.5);
  options_.skip_is_error = true;
  EXPECT_THROW(grade_part(manifest, 3, options_), std::runtime_error);
}

TEST_F(GraderGrade, ASeedOffsetRendersWithOtherSeeds) {
  Manifest m = read_manifest(options_.manifest_path);
  options_.seed_offset = 40;
  CheckResult r = grade_render(m, m.parts[0].steps[0].renders[0], options_);
  EXPECT_EQ(r.seed, 42u);
  EXPECT_TRUE(r.pass) << r.output;
}

TEST_F(GraderGrade, TheEarlierPartsStateIsOneLine) {
  std::ofstream(options_.manifest_path) << R"({"parts": [
      {"part": 1, "steps": [{"step": 1, "name": "a", "points": 1}]},
      {"part": 2, "steps": [{"step": 1, "name": "b", "points": 1}]},
      {"part": 3, "renders_rest_on": [1, 2], "steps": [{"step": 1, "name": "c", "points": 1}]}]})";
  Manifest m = read_manifest(options_.manifest_path);
  EXPECT_EQ(rests_on_line(m, 1, options_), "");
  EXPECT_EQ(rests_on_line(m, 3, options_),
            "Part 3's renders trace rays with your Part 1 and Part 2: Part 1 not graded yet "
            "(grader --part 1), Part 2 not graded yet (grader --part 2).");
  record_part1_passing_part2_failing(m);
  std::string line = rests_on_line(m, 3, options_);
  EXPECT_NE(line.find("Part 1 passed ("), std::string::npos) << line;
  EXPECT_NE(line.find("Part 2 has 1 failing step ("), std::string::npos) << line;
  options_.isolated = true;
  EXPECT_NE(rests_on_line(m, 3, options_).find("the complete solution of Part 1 and Part 2"),
            std::string::npos);
}

// A part changed since it was graded is told by its files' content, not their times: an edit
// with its time put back is seen, and an edit undone within the same second is not a change.
TEST_F(GraderGrade, AChangeIsToldByContentNotByTime) {
  std::ofstream(options_.manifest_path) << R"({"parts": [
      {"part": 1, "steps": [{"step": 1, "name": "a", "points": 1}]},
      {"part": 2, "renders_rest_on": [1], "steps": [{"step": 1, "name": "b", "points": 1}]}]})";
  const Manifest m = read_manifest(options_.manifest_path);
  const fs::path file = root_ / "parts" / "1-raygen" / "camera_ray.cpp";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "float f() { return 1.0f; }\n";
  const fs::file_time_type when = fs::last_write_time(file);
  PartResult one;
  one.part = 1;
  one.files = folder_fingerprint(file.parent_path().string());
  one.steps.push_back(score_step(m.parts[0].steps[0], {CheckResult{"part1.step1.a.x", "test", false, false, "failed", 0.0, 0}}));
  record_state(one, options_);
  EXPECT_EQ(rests_on_line(m, 2, options_).find("changed since"), std::string::npos);
  // Another answer of the same length, written with the time the graded file had.
  std::ofstream(file) << "float f() { return 2.0f; }\n";
  fs::last_write_time(file, when);
  EXPECT_NE(rests_on_line(m, 2, options_).find("changed since"), std::string::npos)
      << rests_on_line(m, 2, options_);
  PartResult two;
  two.part = 2;
  two.steps.push_back(score_step(m.parts[1].steps[0], {CheckResult{"part2.step1.b.x", "render", false, false, "failed", 0.0, 0}}));
  compare_with_gradescope(m, two, options_);
  EXPECT_EQ(two.changed_parts_run, std::vector<int>{1});
  std::ostringstream table;
  print_score_table(table, {two});
  EXPECT_NE(table.str().find("Part 1 changed since it was last graded"), std::string::npos) << table.str();
  // Undone: the graded content again, whatever the time says.
  std::ofstream(file) << "float f() { return 1.0f; }\n";
  fs::last_write_time(file, when + std::chrono::hours(1));
  EXPECT_EQ(rests_on_line(m, 2, options_).find("changed since"), std::string::npos)
      << rests_on_line(m, 2, options_);
  compare_with_gradescope(m, two, options_);
  EXPECT_TRUE(two.changed_parts_run.empty());
  EXPECT_NE(folder_fingerprint(file.parent_path().string()), "");
}

// A render belongs to the latest step it runs; when it fails, its message says how the earlier
// steps of its part that it rests on stand (docs/grading.md), from their tests in this run.
TEST(GraderRestsOn, AFailingRenderSaysHowTheStepsItRestsOnStand) {
  PartSpec part;
  part.part = 1;
  for (const char* name : {"camera_ray", "pixel_loop", "triangle"}) {
    StepSpec st;
    st.part = 1;
    st.step = int(part.steps.size()) + 1;
    st.name = name;
    part.steps.push_back(st);
  }
  RenderCheck render;
  render.rests_on_steps = {1, 2};
  // {failed, counted} by step number (index 0 unused).
  const std::string failing = render_rests_on_line(part, render, {{0, 0}, {0, 3}, {2, 3}, {0, 4}});
  EXPECT_NE(failing.find("1 (camera_ray: its checks pass)"), std::string::npos) << failing;
  EXPECT_NE(failing.find("2 (pixel_loop: 2 of 3 checks fail)"), std::string::npos) << failing;
  EXPECT_NE(failing.find("fix the failing step first"), std::string::npos) << failing;
  const std::string passing = render_rests_on_line(part, render, {{0, 0}, {0, 3}, {0, 3}, {1, 4}});
  EXPECT_NE(passing.find("their checks pass, so look first at this step's code"), std::string::npos)
      << passing;
  // An earlier part the render runs fails: this step is not the first place to look.
  EarlierParts parts;
  parts.failing = {4};
  const std::string earlier = render_rests_on_line(part, render, {{0, 0}, {0, 3}, {0, 3}, {1, 4}}, parts);
  EXPECT_EQ(earlier.find("look first at this step's code"), std::string::npos) << earlier;
  EXPECT_NE(earlier.find("also runs your Part 4, which fails"), std::string::npos) << earlier;
  parts.failing.clear();
  parts.unknown = {3, 4};
  const std::string unknown = render_rests_on_line(part, render, {{0, 0}, {0, 3}, {0, 3}, {1, 4}}, parts);
  EXPECT_NE(unknown.find("Parts 3 and 4, not graded since"), std::string::npos) << unknown;
  render.rests_on_steps.clear();
  EXPECT_NE(render_rests_on_line(part, render, {}).find("only this step's functions"),
            std::string::npos);
  parts.failing = {4};
  EXPECT_EQ(render_rests_on_line(part, render, {}, parts).find("look first"), std::string::npos);
}

// The earlier parts a part's renders run, from state.json: failing as last graded, or unknown.
TEST_F(GraderGrade, TheEarlierPartsARenderRunsAreReadFromTheirRecords) {
  std::ofstream(options_.manifest_path) << R"({"parts": [
      {"part": 1, "steps": [{"step": 1, "name": "a", "points": 1}]},
      {"part": 2, "steps": [{"step": 1, "name": "b", "points": 1}]},
      {"part": 3, "renders_rest_on": [1, 2], "steps": [{"step": 1, "name": "c", "points": 1}]}]})";
  const Manifest m = read_manifest(options_.manifest_path);
  EarlierParts none = earlier_parts(m, 3, options_);
  EXPECT_EQ(none.unknown, (std::vector<int>{1, 2}));
  record_part1_passing_part2_failing(m);
  const EarlierParts parts = earlier_parts(m, 3, options_);
  EXPECT_EQ(parts.failing, std::vector<int>{2});
  EXPECT_TRUE(parts.unknown.empty());
  options_.isolated = true;
  EXPECT_TRUE(earlier_parts(m, 3, options_).failing.empty());
}

TEST_F(GraderGrade, AReferenceThatDoesNotMatchItsChecksumIsRefused) {
  std::ofstream(root_ / "reference" / "ref.exr", std::ios::app) << "tampered";
  Manifest m = read_manifest(options_.manifest_path);
  CheckResult r = grade_render(m, m.parts[0].steps[0].renders[0], options_);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.output.find("checksum"), std::string::npos) << r.output;
}

TEST_F(GraderGrade, AMissingReferenceSaysHowToMakeIt) {
  fs::remove(root_ / "reference" / "ref.exr");
  Manifest m = read_manifest(options_.manifest_path);
  CheckResult r = grade_render(m, m.parts[0].steps[0].renders[0], options_);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.output.find("--make-reference"), std::string::npos) << r.output;
}

TEST_F(GraderGrade, ABadManifestNamesTheEntry) {
  std::ofstream(options_.manifest_path) << R"({"parts": [{"part": 1, "steps": [{"step": 1,
      "name": "a", "points": 1, "renders": [{"name": "x", "scene": "s", "kind": "normals"}]}]}]})";
  try {
    read_manifest(options_.manifest_path);
    FAIL() << "a render without args was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("render \"x\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("args"), std::string::npos) << e.what();
  }
}

// Steps whose tests run each other would charge a failure back and forth (step_at_fault.h): the
// manifest refuses them, and a step that names one the part does not have.
TEST_F(GraderGrade, StepsWhoseTestsRunEachOtherAreRefused) {
  auto refused = [&](const std::string& json, const std::string& words) {
    std::ofstream(options_.manifest_path) << json;
    try {
      read_manifest(options_.manifest_path);
      ADD_FAILURE() << "accepted: " << json;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(R"({"parts": [{"part": 1, "steps": [
      {"step": 1, "name": "a", "points": 1, "tests_rest_on_steps": [2]},
      {"step": 2, "name": "b", "points": 1, "tests_rest_on_steps": [1]}]}]})",
          "step 1: its tests run step 2, whose tests run it in turn");
  refused(R"({"parts": [{"part": 1, "steps": [
      {"step": 1, "name": "a", "points": 1, "tests_rest_on_steps": [3]}]}]})",
          "names step 3, which the part does not have");
  std::ofstream(options_.manifest_path) << R"({"parts": [{"part": 1, "steps": [
      {"step": 1, "name": "a", "points": 1, "tests_rest_on_steps": [2]},
      {"step": 2, "name": "b", "points": 1}]}]})";
  EXPECT_EQ(read_manifest(options_.manifest_path).parts[0].steps[0].tests_rest_on_steps,
            std::vector<int>{2});
}

// The project's own rubric: every reference recorded, no two graded checks on one image (the
// normals of two scenes that differ only in materials are one image), every step with points.
TEST(GraderManifest, TheProjectsRubricHasDistinctReferencesAndPointsInEveryStep) {
  const Manifest m = read_manifest(std::string(pt::test::source_dir()) + "/reference/manifest.json");
  std::map<std::string, std::string> seen;
  for (const PartSpec& p : m.parts) {
    EXPECT_GT(p.points(), 0.0) << "part " << p.part;
    for (const StepSpec& s : p.steps) EXPECT_GT(s.points, 0.0) << s.full_name();
    for (const RenderCheck* r : p.renders()) {
      EXPECT_FALSE(r->checksum.empty()) << r->name << ": no reference recorded";
      if (r->checksum.empty()) continue;
      auto [at, fresh] = seen.emplace(r->checksum, r->name);
      EXPECT_TRUE(fresh) << r->name << " and " << at->second << " compare with the same image";
    }
  }
}

TEST(GraderTree, TheTreeGradedSaysWhetherItsSolutionIsSeparate) {
  // A grader grading another build tree (a mutant's copy) reads that tree's configuration.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("pt-grader-tree-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  EXPECT_FALSE(has_separate_solution(dir.string()).has_value()) << "no CMakeCache.txt";
  auto write_cache = [&](const std::string& solution) {
    std::ofstream(dir / "CMakeCache.txt") << "CMAKE_HOME_DIRECTORY:INTERNAL=" << dir.string()
                                          << "\nPT_SOLUTION_DIR:PATH=" << solution << "\n";
  };
  write_cache("");
  EXPECT_EQ(has_separate_solution(dir.string()), std::optional<bool>(false));
  write_cache(dir.string());  // its own sources: the ordinary targets are the solution
  EXPECT_EQ(has_separate_solution(dir.string()), std::optional<bool>(false));
  write_cache("/somewhere/else/solution");
  EXPECT_EQ(has_separate_solution(dir.string()), std::optional<bool>(true));
  std::filesystem::remove_all(dir);
}

TEST_F(GraderGrade, OnlyTheAssignmentsStoppingRuleIsGraded) {
  // Part 5's two renders, one per rule: the manifest's rule grades one, the other keeps its
  // reference (made all the same) and is not graded.
  auto manifest_with = [&](const std::string& rule, const std::string& extra) {
    std::ofstream(options_.manifest_path) << R"({"stopping_rule": ")" + rule + R"(", "parts": [
      {"part": 5, "steps": [{"step": 1, "name": "loop", "points": 1, "renders": [
        {"name": "a", "scene": "s", "kind": "adaptive", "args": [], "reference_args": [],
         "seed": 7, "reference_seed": 1, "reference": "r", "stopping_rule": "split"},
        {"name": "b", "scene": "s", "kind": "adaptive", "args": [], "reference_args": [],
         "seed": 7, "reference_seed": 1000, "reference_runs": 64, "reference": "r2",
         "stopping_rule": "course")" + extra + R"(}]}]}]})";
    return read_manifest(options_.manifest_path);
  };
  for (const char* rule : {"split", "course"}) {
    const Manifest m = manifest_with(rule, "");
    ASSERT_EQ(m.parts[0].renders().size(), 1u);
    EXPECT_EQ(m.parts[0].renders()[0]->stopping_rule, rule);
    EXPECT_EQ(m.parts[0].renders_of_every_rule().size(), 2u);
  }
  EXPECT_EQ(manifest_with("course", "").parts[0].renders()[0]->reference_runs, 64);
  // A graded seed among the reference's own (1000 to 1063) would share its random numbers.
  try {
    manifest_with("course", R"(, "seed": 1010)");
    ADD_FAILURE() << "a graded seed among the reference's was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("one of the reference's"), std::string::npos) << e.what();
  }
  EXPECT_THROW(manifest_with("fair", ""), std::runtime_error);
  try {
    manifest_with("course", R"(, "reference_runs": 0)");
    ADD_FAILURE() << "a reference of no renders was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("reference_runs"), std::string::npos) << e.what();
  }
}

TEST_F(GraderGrade, AReferenceOfSeveralRunsIsTheirMeanAndLeavesNothingBeside) {
  // reference_runs renders (seeds 50, 51, 52) averaged into the reference; their files, and the
  // sample-rate images an adaptive render writes beside its output, stay out of reference/.
  nlohmann::ordered_json m = nlohmann::ordered_json::parse(std::ifstream(options_.manifest_path));
  // The good render alone (the hang would take a minute).
  m["parts"][0]["steps"] = nlohmann::ordered_json::array({m["parts"][0]["steps"][0]});
  auto& render = m["parts"][0]["steps"][0]["renders"][0];
  render["reference_seed"] = 50;
  render["reference_runs"] = 3;
  render["reference"] = "reference/averaged.exr";
  std::ofstream(options_.manifest_path) << m.dump(2);
  const Manifest manifest = read_manifest(options_.manifest_path);
  EXPECT_TRUE(make_references(manifest, 3, options_));
  const RenderEstimate made = read_estimate_exr((root_ / "reference" / "averaged.exr").string());
  const RenderEstimate one = read_estimate_exr((root_ / "scenes" / "good.exr").string());
  EXPECT_EQ(made.mean, one.mean) << "the mean of three copies of one render is that render";
  EXPECT_EQ(made.count[0], 3.0f * one.count[0]);
  const Manifest after = read_manifest(options_.manifest_path);
  const RenderCheck* r = after.find_render("part3.step1.render.good.exr");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->checksum, file_checksum((root_ / "reference" / "averaged.exr").string()));
  const std::string runs =
      nlohmann::ordered_json::parse(std::ifstream(options_.manifest_path))["parts"][0]["steps"][0]
                                    ["renders"][0]["made"].value("runs", "");
  EXPECT_NE(runs.find("seeds 50 to 52"), std::string::npos) << runs;
  for (const auto& entry : fs::directory_iterator(root_ / "reference"))
    EXPECT_TRUE(entry.path().filename() == "averaged.exr" || entry.path().filename() == "ref.exr" ||
                entry.path().filename() == "manifest.json")
        << entry.path() << " left in reference/";
}

TEST(GraderTree, APart5BuildOfAnotherStoppingRuleIsNamed) {
  // The stopping rule is compiled into the build (its tests, the renderer's default): grading
  // Part 5 under the other rule would hold the student to the wrong one.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("pt-grader-rule-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Manifest m;
  m.stopping_rule = "split";
  EXPECT_EQ(stopping_rule_mismatch(m, dir.string()), "") << "no CMakeCache.txt: nothing to say";
  std::ofstream(dir / "CMakeCache.txt") << "PT_ASSIGNMENT_STOPPING_RULE:INTERNAL=course\n";
  const std::string why = stopping_rule_mismatch(m, dir.string());
  EXPECT_NE(why.find("course stopping rule"), std::string::npos) << why;
  EXPECT_NE(why.find("asks for the split rule"), std::string::npos) << why;
  m.stopping_rule = "course";
  EXPECT_EQ(stopping_rule_mismatch(m, dir.string()), "");
  std::filesystem::remove_all(dir);
}

TEST(GraderTimeLimits, ABusyMachineStretchesTheLimitWithinBounds) {
  EXPECT_DOUBLE_EQ(load_scaled_limit(60.0, 0.5, 2), 60.0);   // idle: the limit as given
  EXPECT_DOUBLE_EQ(load_scaled_limit(60.0, 9.0, 2), 270.0);  // 4.5 processes a core
  EXPECT_DOUBLE_EQ(load_scaled_limit(60.0, 500.0, 2), 60.0 * kMaxLoadFactor);  // an endless loop ends
  EXPECT_DOUBLE_EQ(load_scaled_limit(60.0, std::nan(""), 2), 60.0);
  EXPECT_DOUBLE_EQ(load_scaled_limit(60.0, 4.0, 0), 60.0);
  EXPECT_GE(load_scaled_limit(60.0), 60.0);
}

}  // namespace
}  // namespace pt::grader
