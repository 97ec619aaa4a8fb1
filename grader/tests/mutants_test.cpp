// The mutant machinery: the catalogue is well formed and every patch applies to the complete
// solution; a scratch tree copies, patches and restores without touching its source; and the
// verdict reads a grader's results the way the table says.
#include "framework/testing/test_paths.h"
#include "grader/mutants.h"

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"
#include "framework/text/text_file.h"
#include "grader/handout.h"
#include "grader/scratch_tree.h"
#include "grader/second_solution.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace pt::grader {
namespace {

const fs::path kIndex = fs::path(pt::test::source_dir()) / "grader" / "mutants" / "index.json";

TEST(MutantCatalogue, HasAtLeastTwentyFiveBugsOverEveryPart) {
  std::vector<MutantSpec> specs = read_mutant_index(kIndex.string());
  EXPECT_GE(specs.size(), 25u);
  std::set<int> parts;
  std::set<std::string> names;
  for (const MutantSpec& s : specs) {
    parts.insert(s.part);
    EXPECT_TRUE(names.insert(s.name).second) << s.name << " twice";
    EXPECT_TRUE(fs::exists(kIndex.parent_path() / s.patch)) << s.patch;
    EXPECT_FALSE(s.cause.empty()) << s.name << " names no cause";
  }
  EXPECT_EQ(parts, (std::set<int>{1, 2, 3, 4, 5}));
}

TEST(MutantCatalogue, EveryPatchAndTheSecondSolutionApplyToTheCompleteSolution) {
  // Only the files the patches touch are copied: a full scratch tree is the command's job.
  test::TempFolder tmp("pt-mutant-apply");
  std::vector<std::string> patches;
  for (const MutantSpec& s : read_mutant_index(kIndex.string()))
    patches.push_back((kIndex.parent_path() / s.patch).string());
  for (const std::string& p : second_solution_patches(pt::test::source_dir())) patches.push_back(p);
  for (const std::string& p : patches) {
    fs::path root = tmp.path() / fs::path(p).stem();
    for (const std::string& rel : patched_files(read_text_file(p))) {
      fs::create_directories((root / rel).parent_path());
      fs::copy_file(fs::path(pt::test::source_dir()) / rel, root / rel);
    }
    ScratchTree tree(pt::test::source_dir(), root.string());
    // apply() needs the copy to be a repository of its own, as sync() makes it.
    ASSERT_EQ(std::system(("git init -q " + root.string()).c_str()), 0);
    EXPECT_NO_THROW(tree.apply(p)) << p;
  }
}

TEST(MutantCatalogue, TheHandoutLeavesItOut) {
  EXPECT_TRUE(in_solution_only_folder(pt::test::source_dir(), "grader/mutants/index.json"));
  EXPECT_TRUE(in_solution_only_folder(pt::test::source_dir(), "grader/second_solution/1-raygen.patch"));
  EXPECT_FALSE(in_solution_only_folder(pt::test::source_dir(), "grader/mutants.cpp"));
  EXPECT_FALSE(in_solution_only_folder(pt::test::source_dir(), "parts/1-raygen/camera_ray.cpp"));
}

TEST(ScratchTree, CopiesPatchesAndRestoresWithoutTouchingItsSource) {
  test::TempFolder tmp("pt-scratch");
  fs::path src = tmp.path() / "src";
  tmp.write("src/a.txt", "one\ntwo\nthree\n");
  tmp.write("src/dir/b.txt", "bee\n");
  ASSERT_EQ(std::system(("cd " + src.string() + " && git init -q && git add a.txt dir/b.txt").c_str()), 0);
  tmp.write("fix.patch",
            "a comment line before the diff\n"
            "--- a/a.txt\n+++ b/a.txt\n@@ -1,3 +1,3 @@\n one\n-two\n+TWO\n three\n");
  ScratchTree tree(src.string(), (tmp.path() / "copy").string());
  EXPECT_EQ(tree.sync(), 2);
  EXPECT_EQ(tree.sync(), 0) << "an unchanged file must not be rewritten (the build stays incremental)";
  tree.apply((tmp.path() / "fix.patch").string());
  EXPECT_EQ(read_text_file(tmp.path() / "copy" / "a.txt"), "one\nTWO\nthree\n");
  EXPECT_EQ(read_text_file(src / "a.txt"), "one\ntwo\nthree\n");
  tree.restore();
  EXPECT_EQ(read_text_file(tmp.path() / "copy" / "a.txt"), "one\ntwo\nthree\n");
  tmp.write("bad.patch", "--- a/a.txt\n+++ b/a.txt\n@@ -1,1 +1,1 @@\n-nothing like it\n+x\n");
  try {
    tree.apply((tmp.path() / "bad.patch").string());
    FAIL() << "a patch that does not apply was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.patch"), std::string::npos) << e.what();
  }
}

MutantSpec spec(const std::string& step, const std::string& hint) {
  MutantSpec s;
  s.name = "99-test";
  s.part = 3;
  s.step = step;
  s.hint = hint;
  return s;
}

json step_results(double importance_score, double bsdf_score, const std::string& message) {
  return {{"tests",
           {{{"name", "part3.step1.diffuse_bsdf"}, {"score", bsdf_score}, {"max_score", 4}, {"output", "bsdf: 1 of 3 checks failed"}},
            {{"name", "part3.step4.importance"}, {"score", importance_score}, {"max_score", 9}, {"output", message}}}}};
}

TEST(MutantVerdict, OwnStepOnlyWithATrueHintIsOk) {
  MutantOutcome o = judge_mutant(spec("part3.step4.importance", "shadow|leak"),
                                 step_losses(step_results(4.5, 4, "too bright: light leaks through a thin gap")));
  EXPECT_EQ(o.verdict, "ok");
  ASSERT_EQ(o.losses.size(), 1u);
  EXPECT_DOUBLE_EQ(o.losses[0].lost, 4.5);
}

TEST(MutantVerdict, AnUntrueHintAPassAndAWrongStepAreEachNamed) {
  MutantSpec s = spec("part3.step4.importance", "shadow|leak");
  EXPECT_EQ(judge_mutant(s, step_losses(step_results(4.5, 4, "wrong root?"))).verdict, "hint?");
  // The mutant's name in a diff image's path is no hint.
  s.name = "26-shadow-epsilon";
  s.hint = "shadow";
  EXPECT_EQ(judge_mutant(s, step_losses(step_results(4.5, 4, "light counted twice? (diff: out/26-shadow-epsilon/x.png)"))).verdict, "hint?");
  s = spec("part3.step4.importance", "shadow|leak");
  EXPECT_EQ(judge_mutant(s, step_losses(step_results(9, 4, ""))).verdict, "PASSES");
  EXPECT_EQ(judge_mutant(s, step_losses(step_results(9, 2, ""))).verdict, "WRONG STEP");
  EXPECT_EQ(judge_mutant(s, step_losses(step_results(4.5, 2, "leak"))).verdict, "ALSO ELSEWHERE");
}

// A bug worth more than its step: all of its step's points lost, the rest where it shows, in a
// step whose message names the mutant's step as the one at fault. Named apart from "ok".
TEST(MutantVerdict, ABugWorthMoreThanItsStepIsAnOverflowNotOk) {
  MutantSpec s = spec("part3.step1.diffuse_bsdf", "albedo");
  json results = {{"tests",
                   {{{"name", "part3.step1.diffuse_bsdf"}, {"score", 0}, {"max_score", 4}, {"output", "albedo off"}},
                    {{"name", "part3.step4.importance"}, {"score", 8}, {"max_score", 9},
                     {"output", "x runs step 1 (part3.step1.diffuse_bsdf), which fails: 0.5 stay here"}}}}};
  EXPECT_EQ(judge_mutant(s, step_losses(results)).verdict, "OVERFLOW");
  results["tests"][1]["output"] = "look first at this step's code";
  EXPECT_EQ(judge_mutant(s, step_losses(results)).verdict, "ALSO ELSEWHERE");
  results["tests"][1]["output"] = "x runs step 1 (part3.step1.diffuse_bsdf), which fails";
  results["tests"][0]["score"] = 1;
  EXPECT_EQ(judge_mutant(s, step_losses(results)).verdict, "ALSO ELSEWHERE");
}

// Per rule: each mutant's verdict and whether its step's message names the rule it breaks.
TEST(MutantVerdict, TheRuleTableSaysWhetherTheHintNamesTheRule) {
  Manifest m;
  PartSpec p;
  p.part = 3;
  StepSpec s;
  s.part = 3;
  s.step = 4;
  s.name = "importance";
  s.rules = {{"several_lights", "every light adds its light", {}, {"28-x", "29-y"}},
             {"unbroken", "nothing breaks it", {}, {}}};
  p.steps.push_back(s);
  m.parts.push_back(p);
  MutantOutcome named, unnamed;
  named.spec.name = "28-x";
  named.verdict = "ok";
  named.message = "x: 0.333x\nThe rule it checks, #several_lights: every light adds its light";
  unnamed.spec.name = "29-y";
  unnamed.verdict = "hint?";
  unnamed.message = "x: failed";
  std::ostringstream out;
  print_rule_table(out, m, {named, unnamed});
  const std::string t = out.str();
  EXPECT_NE(t.find("part3.step4.importance#several_lights"), std::string::npos) << t;
  EXPECT_NE(t.find("28-x                            ok              yes"), std::string::npos) << t;
  EXPECT_NE(t.find("29-y                            hint?           no"), std::string::npos) << t;
  EXPECT_NE(t.find("1 of 2 rules broken by a mutant of this run"), std::string::npos) << t;
}

TEST(MutantVerdict, PerCheckResultsGiveEachFailingTestsShareToItsStep) {
  json results = {{"tests",
                   {{{"name", "part3.build"}, {"score", 0}, {"max_score", 0}, {"output", "built"}},
                    {{"name", "part3.tests"}, {"score", 8}, {"max_score", 10},
                     {"output", "8 of 10 tests passed\n    failed: part3.step4.importance.a\n    failed: part3.step4.importance.b"}},
                    {{"name", "part3.direct.cornell_spheres"}, {"score", 0}, {"max_score", 5}, {"output", "too dark"}}}}};
  std::vector<StepLoss> losses = step_losses(results);
  ASSERT_EQ(losses.size(), 2u);
  EXPECT_EQ(losses[0].step, "part3.step4.importance");
  EXPECT_DOUBLE_EQ(losses[0].lost, 2.0);
  EXPECT_EQ(losses[1].step, "part3.direct.cornell_spheres");
}

TEST(MutantCatalogue, AMalformedIndexIsNamed) {
  test::TempFolder tmp("pt-mutant-index");
  fs::path p = tmp.write("index.json", R"({"mutants": [{"name": "x", "patch": "x.patch", "part": 2, "step": "part3.step1.a"}]})");
  try {
    read_mutant_index(p.string());
    FAIL() << "a step of another part was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("mutant 1 (x)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pt::grader

namespace pt::grader {
namespace {

// The whole run on a tiny project: a catalogue of two patches, a CMake project that configures
// in a second, and a stand-in grader that takes points from step 1 when the copy's source says
// "bug" and from step 2 when it says "slow". One mutant is caught in its own step, the other in
// the wrong one; the source is never changed and the copy is back to it afterwards.
TEST(MutantRun, AppliesGradesJudgesAndRestoresEachMutant) {
  test::TempFolder tmp("pt-mutant-run");
  fs::path src = tmp.path() / "project";
  tmp.write("project/CMakeLists.txt", "cmake_minimum_required(VERSION 3.16)\nproject(tiny NONE)\n");
  tmp.write("project/code.txt", "fine\n");
  ASSERT_EQ(std::system(("cd " + src.string() + " && git init -q && git add CMakeLists.txt code.txt").c_str()), 0);
  tmp.write("project/grader/mutants/1-bug.patch",
            "--- a/code.txt\n+++ b/code.txt\n@@ -1 +1 @@\n-fine\n+bug\n");
  tmp.write("project/grader/mutants/2-slow.patch",
            "--- a/code.txt\n+++ b/code.txt\n@@ -1 +1 @@\n-fine\n+slow\n");
  fs::path index = tmp.write("project/grader/mutants/index.json", R"({"mutants": [
    {"name": "1-bug", "patch": "1-bug.patch", "part": 1, "step": "part1.step1.one", "hint": "bug here"},
    {"name": "2-slow", "patch": "2-slow.patch", "part": 1, "step": "part1.step1.one", "hint": "slow"}]})");
  fs::path grader = tmp.write("fake-grader",
      "#!/bin/sh\n"
      "[ \"$1\" = --help ] && { echo 'usage'; exit 0; }\n"
      "while [ $# -gt 0 ]; do case $1 in --source) src=$2;; --json) out=$2;; esac; shift; done\n"
      "one=3; two=3; msg=ok\n"
      "grep -q bug \"$src/code.txt\" && { one=0; msg='a bug here'; }\n"
      "grep -q slow \"$src/code.txt\" && two=1\n"
      "printf '{\"tests\": [{\"name\": \"part1.step1.one\", \"score\": %s, \"max_score\": 3, \"output\": \"%s\"},"
      " {\"name\": \"part1.step2.two\", \"score\": %s, \"max_score\": 3, \"output\": \"too slow\"}]}' "
      "$one \"$msg\" $two > \"$out\"\n"
      "exit 1\n");
  fs::permissions(grader, fs::perms::owner_all);
  MutantRunOptions o;
  o.source_dir = src.string();
  o.index_path = index.string();
  o.work_dir = (tmp.path() / "work").string();
  o.grader_exe = grader.string();
  std::ostringstream log;
  std::vector<MutantOutcome> out = run_mutants(o, log);
  ASSERT_EQ(out.size(), 2u) << log.str();
  EXPECT_EQ(out[0].verdict, "ok") << out[0].message << "\n" << log.str();
  EXPECT_EQ(out[1].verdict, "WRONG STEP") << out[1].message;
  ASSERT_EQ(out[1].losses.size(), 1u);
  EXPECT_EQ(out[1].losses[0].step, "part1.step2.two");
  EXPECT_DOUBLE_EQ(out[1].losses[0].lost, 2.0);
  EXPECT_EQ(read_text_file(src / "code.txt"), "fine\n");
  EXPECT_EQ(read_text_file(tmp.path() / "work" / "tree-0" / "code.txt"), "fine\n");
  std::ostringstream table;
  print_mutant_table(table, out, 0.0);
  EXPECT_NE(table.str().find("1 of 2 mutants"), std::string::npos) << table.str();
}

}  // namespace
}  // namespace pt::grader
