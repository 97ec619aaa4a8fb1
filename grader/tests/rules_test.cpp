// The rule list: each rule of a step needs a check the build has and a catalogued bug of its own
// step; a failing check says the rule it enforces.
#include "grader/rules.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "grader/grade.h"

namespace pt::grader {
namespace {

Manifest one_step(std::vector<Rule> rules) {
  Manifest m;
  PartSpec p;
  p.part = 3;
  StepSpec s;
  s.part = 3;
  s.step = 4;
  s.name = "importance";
  s.points = 6;
  s.rules = std::move(rules);
  RenderCheck r;
  r.name = "part3.step4.render.box";
  s.renders.push_back(r);
  p.steps.push_back(s);
  m.parts.push_back(p);
  return m;
}

MutantSpec mutant(const std::string& name, const std::string& step) {
  MutantSpec m;
  m.name = name;
  m.part = 3;
  m.step = step;
  return m;
}

bool has(const std::vector<std::string>& problems, const std::string& part) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(part) != std::string::npos; });
}

const std::set<std::string> kTests = {"part3.step4.importance.sums",
                                      "part3.step4.importance.scenes/box_sah",
                                      "part3.step4.importance.scenes/bunny_sah"};

TEST(GraderRules, ACompleteListHasNoProblem) {
  const Manifest m = one_step({{"sum", "every light adds its light",
                                {"part3.step4.importance.sums", "part3.step4.render.box"}, {"28-x"}},
                               {"scenes", "scenes agree", {"part3.step4.importance.scenes"}, {"29-y"}}});
  const std::vector<MutantSpec> mutants = {mutant("28-x", "part3.step4.importance"),
                                           mutant("29-y", "part3.step4.importance")};
  EXPECT_TRUE(rule_problems(m, &mutants, kTests).empty());
  EXPECT_TRUE(rule_problems(m, nullptr, kTests).empty());
}

TEST(GraderRules, EachGapIsNamed) {
  const std::vector<MutantSpec> mutants = {mutant("28-x", "part3.step4.importance"),
                                           mutant("30-z", "part3.step1.diffuse_bsdf")};
  EXPECT_TRUE(has(rule_problems(one_step({}), nullptr, kTests), "part3.step4.importance: states no rule"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {}, {"28-x"}}}), &mutants, kTests),
                  "#a: no check enforces it"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step4.importance.gone"}, {"28-x"}}}),
                                &mutants, kTests),
                  "the check part3.step4.importance.gone is no test or render"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step1.diffuse_bsdf.x"}, {"28-x"}}}),
                                &mutants, kTests),
                  "is not one of part3.step4.importance's"));
  // A prefix of a test's name is not the test.
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step4.importance.sce"}, {"28-x"}}}),
                                &mutants, kTests),
                  "is no test or render"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step4.importance.sums"}, {}}}),
                                &mutants, kTests),
                  "no catalogued bug breaks it alone"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step4.importance.sums"}, {"31-w"}}}),
                                &mutants, kTests),
                  "the mutant 31-w is not in the catalogue"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step4.importance.sums"}, {"30-z"}}}),
                                &mutants, kTests),
                  "must lose points in part3.step1.diffuse_bsdf"));
  EXPECT_TRUE(has(rule_problems(one_step({{"a", "t", {"part3.step4.importance.sums"}, {"28-x"}}}),
                                &mutants, kTests),
                  "the mutant 30-z breaks no rule"));
}

TEST(GraderRules, AFailingCheckSaysTheRuleItEnforces) {
  const Manifest m = one_step({{"sum", "every light adds its own light",
                                {"part3.step4.importance.scenes"}, {}}});
  CheckResult failing;
  failing.name = "part3.step4.importance.scenes/bunny_sah";
  failing.kind = "test";
  failing.output = "0.333x the exact value";
  failing.todo = "    parts/3-direct/x.cpp:3: not implemented";
  StepResult r = score_step(m.parts[0].steps[0], {failing});
  EXPECT_NE(r.message.find("0.333x the exact value\nThe rule it checks, #sum: every light adds "
                           "its own light"),
            std::string::npos)
      << r.message;
  EXPECT_EQ(rules_enforced_by(m.parts[0].steps[0], "part3.step4.importance.other").size(), 0u);
}

// The step's message shows the first failing check whole; the rules of the other failing checks
// are named too, each once, with the checks that hold the code to them.
TEST(GraderRules, TheRulesOfEveryFailingCheckAreNamed) {
  const Manifest m = one_step({{"sum", "every light adds its own light",
                                {"part3.step4.importance.sums"}, {}},
                               {"density", "a sample is divided by its density",
                                {"part3.step4.importance.scenes", "part3.step4.importance.sums"},
                                {}},
                               {"frame", "f and cos in the local frame",
                                {"part3.step4.importance.frames"}, {}}});
  auto check = [](const std::string& name, bool pass) {
    CheckResult c;
    c.name = name;
    c.kind = "test";
    c.pass = pass;
    c.output = pass ? "" : "it failed";
    return c;
  };
  StepResult r = score_step(m.parts[0].steps[0],
                            {check("part3.step4.importance.sums", false),
                             check("part3.step4.importance.scenes/box_sah", false),
                             check("part3.step4.importance.frames", true)});
  EXPECT_NE(r.message.find("#sum: "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("#density: "), std::string::npos) << r.message;
  // Each rule once, and none whose checks all pass.
  EXPECT_EQ(r.message.find("#density: "), r.message.rfind("#density: ")) << r.message;
  EXPECT_EQ(r.message.find("#frame"), std::string::npos) << r.message;
  // A later failing check that adds a rule is listed by its name.
  r = score_step(m.parts[0].steps[0], {check("part3.step4.importance.scenes/box_sah", false),
                                       check("part3.step4.importance.sums", false)});
  EXPECT_NE(r.message.find("Also failing: sums\nThe rule it checks, #sum: "), std::string::npos)
      << r.message;
}

}  // namespace
}  // namespace pt::grader
