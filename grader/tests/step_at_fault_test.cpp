// The step at fault: a failing check that runs another failing step of its part costs that step
// its share, never more than it has, and the part's total is what the checks give whatever is
// charged.
#include "grader/step_at_fault.h"

#include <random>

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

CheckResult check(const std::string& name, const std::string& kind, bool pass) {
  CheckResult c;
  c.name = name;
  c.kind = kind;
  c.pass = pass;
  c.output = pass ? "" : "failed";
  return c;
}

/// A part of three steps of 3, 3 and 6 points; step 2's tests run step 1, step 3's render runs
/// steps 1 and 2.
PartSpec three_steps() {
  PartSpec p;
  p.part = 1;
  const char* names[] = {"camera_ray", "pixel_loop", "triangle"};
  const double points[] = {3, 3, 6};
  for (int k = 1; k <= 3; ++k) {
    StepSpec s;
    s.part = 1;
    s.step = k;
    s.name = names[k - 1];
    s.points = points[k - 1];
    p.steps.push_back(s);
  }
  p.steps[1].tests_rest_on_steps = {1};
  RenderCheck r;
  r.name = "part1.step3.render.box";
  r.part = 1;
  r.step = 3;
  r.rests_on_steps = {1, 2};
  p.steps[2].renders.push_back(r);
  return p;
}

std::vector<StepResult> scored(const PartSpec& p, const std::vector<std::vector<CheckResult>>& checks) {
  std::vector<StepResult> steps;
  for (size_t i = 0; i < p.steps.size(); ++i) steps.push_back(score_step(p.steps[i], checks[i]));
  return steps;
}

double total(const std::vector<StepResult>& steps) {
  double t = 0.0;
  for (const StepResult& s : steps) t += s.score;
  return t;
}

TEST(GraderStepAtFault, ARenderThatFailsWithAnEarlierStepIsChargedThere) {
  const PartSpec p = three_steps();
  std::vector<StepResult> steps =
      scored(p, {{check("part1.step1.camera_ray.a", "test", true)},
                 {check("part1.step2.pixel_loop.a", "test", false),
                  check("part1.step2.pixel_loop.b", "test", true),
                  check("part1.step2.pixel_loop.c", "test", true)},
                 {check("part1.step3.triangle.a", "test", true),
                  check("part1.step3.render.box", "render", false)}});
  const double before = total(steps);
  charge_steps_at_fault(p, steps);
  EXPECT_DOUBLE_EQ(total(steps), before);
  // The render's share (3) goes to step 2, which has 2 left to lose; 1 stays on step 3.
  EXPECT_DOUBLE_EQ(steps[2].score, 5.0) << steps[2].message;
  EXPECT_DOUBLE_EQ(steps[1].score, 0.0) << steps[1].message;
  EXPECT_NE(steps[2].message.find("runs step 2 (part1.step2.pixel_loop), which fails"),
            std::string::npos)
      << steps[2].message;
  EXPECT_NE(steps[2].message.find("1.00 stay here"), std::string::npos) << steps[2].message;
  EXPECT_NE(steps[1].message.find("Charged 2.00 points for part1.step3.render.box"),
            std::string::npos)
      << steps[1].message;
}

TEST(GraderStepAtFault, TheEarliestFailingStepItRunsIsTheOneCharged) {
  const PartSpec p = three_steps();
  std::vector<StepResult> steps =
      scored(p, {{check("part1.step1.camera_ray.a", "test", false),
                  check("part1.step1.camera_ray.b", "test", true),
                  check("part1.step1.camera_ray.c", "test", true),
                  check("part1.step1.camera_ray.d", "test", true)},
                 {check("part1.step2.pixel_loop.a", "test", false),
                  check("part1.step2.pixel_loop.b", "test", true)},
                 {check("part1.step3.triangle.a", "test", true),
                  check("part1.step3.triangle.b", "test", true),
                  check("part1.step3.render.box", "render", false)}});
  const double before = total(steps);
  charge_steps_at_fault(p, steps);
  EXPECT_DOUBLE_EQ(total(steps), before);
  // Step 2's test (1.5) and step 3's render (2) go to step 1, which has 2.25 to lose.
  EXPECT_DOUBLE_EQ(steps[0].score, 0.0);
  EXPECT_DOUBLE_EQ(steps[1].score, 3.0);
  EXPECT_DOUBLE_EQ(steps[2].score, 6.0 - (2.0 - 0.75));
  EXPECT_NE(steps[2].message.find("runs step 1"), std::string::npos) << steps[2].message;
}

TEST(GraderStepAtFault, AFailureWithTheStepsItRunsPassingStaysItsOwn) {
  const PartSpec p = three_steps();
  std::vector<StepResult> steps =
      scored(p, {{check("part1.step1.camera_ray.a", "test", true)},
                 {check("part1.step2.pixel_loop.a", "test", true)},
                 {check("part1.step3.triangle.a", "test", false),
                  check("part1.step3.render.box", "render", false)}});
  charge_steps_at_fault(p, steps);
  EXPECT_DOUBLE_EQ(steps[0].score, 3.0);
  EXPECT_DOUBLE_EQ(steps[1].score, 3.0);
  EXPECT_DOUBLE_EQ(steps[2].score, 0.0);
  EXPECT_EQ(steps[2].message.find("charged"), std::string::npos) << steps[2].message;
}

// A test of step 3 runs no other step (its step names none), so a failing step 1 takes none of
// its loss.
TEST(GraderStepAtFault, OnlyWhatAStepRunsIsCharged) {
  const PartSpec p = three_steps();
  std::vector<StepResult> steps =
      scored(p, {{check("part1.step1.camera_ray.a", "test", false),
                  check("part1.step1.camera_ray.b", "test", true)},
                 {check("part1.step2.pixel_loop.a", "test", true)},
                 {check("part1.step3.triangle.a", "test", false),
                  check("part1.step3.render.box", "render", true)}});
  charge_steps_at_fault(p, steps);
  EXPECT_DOUBLE_EQ(steps[0].score, 1.5);
  EXPECT_DOUBLE_EQ(steps[2].score, 3.0);
}

// A step's tests may run a later step (Part 4's path tests compare with the student's own step 2
// on the same random numbers): when that step fails too, it is charged.
TEST(GraderStepAtFault, ALaterStepATestRunsIsChargedToo) {
  PartSpec p = three_steps();
  p.steps[0].tests_rest_on_steps = {2};
  p.steps[1].tests_rest_on_steps = {};  // the manifest allows no steps that run each other
  std::vector<StepResult> steps =
      scored(p, {{check("part1.step1.camera_ray.a", "test", false),
                  check("part1.step1.camera_ray.b", "test", true)},
                 {check("part1.step2.pixel_loop.a", "test", false),
                  check("part1.step2.pixel_loop.b", "test", true),
                  check("part1.step2.pixel_loop.c", "test", true)},
                 {check("part1.step3.triangle.a", "test", true)}});
  const double before = total(steps);
  charge_steps_at_fault(p, steps);
  EXPECT_DOUBLE_EQ(total(steps), before);
  EXPECT_DOUBLE_EQ(steps[0].score, 3.0) << steps[0].message;
  EXPECT_DOUBLE_EQ(steps[1].score, 2.0 - 1.5) << steps[1].message;
  EXPECT_NE(steps[0].message.find("runs step 2 (part1.step2.pixel_loop), which fails"),
            std::string::npos)
      << steps[0].message;
}

// A later step whose only failures run the earlier step (a render of it) is not charged for the
// earlier step's own failing tests: the earlier step's bug shows in both, and stays its own.
TEST(GraderStepAtFault, ALaterStepFailingOnlyThroughThisOneIsNotCharged) {
  PartSpec p = three_steps();
  p.steps[0].tests_rest_on_steps = {3};
  p.steps[1].tests_rest_on_steps = {};
  std::vector<StepResult> steps =
      scored(p, {{check("part1.step1.camera_ray.a", "test", false),
                  check("part1.step1.camera_ray.b", "test", true)},
                 {check("part1.step2.pixel_loop.a", "test", true)},
                 {check("part1.step3.triangle.a", "test", true),
                  check("part1.step3.render.box", "render", false)}});
  const double before = total(steps);
  charge_steps_at_fault(p, steps);
  EXPECT_DOUBLE_EQ(total(steps), before);
  // Step 1 loses its own 1.5 and takes 1.5 of the render's 3; the rest stays in step 3.
  EXPECT_DOUBLE_EQ(steps[0].score, 0.0) << steps[0].message;
  EXPECT_DOUBLE_EQ(steps[2].score, 4.5) << steps[2].message;
  EXPECT_EQ(steps[0].message.find("which fails: fix that step first"), std::string::npos)
      << steps[0].message;
}

// Whatever passes and fails, the part's total is the checks' and no step leaves [0, points]: a
// submission cannot raise its score by breaking a step on purpose, even where two steps run each
// other (which the manifest refuses).
TEST(GraderStepAtFault, TheTotalNeverMoves) {
  PartSpec p = three_steps();
  p.steps[0].tests_rest_on_steps = {2};
  std::mt19937 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::vector<CheckResult>> checks(3);
    const int n[] = {1 + int(rng() % 4), 1 + int(rng() % 4), 1 + int(rng() % 4)};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < n[k]; ++i)
        checks[size_t(k)].push_back(check("part1.step" + std::to_string(k + 1) + ".s.t" +
                                              std::to_string(i),
                                          "test", rng() % 2 == 0));
    checks[2].push_back(check("part1.step3.render.box", "render", rng() % 2 == 0));
    std::vector<StepResult> steps = scored(p, checks);
    const double before = total(steps);
    charge_steps_at_fault(p, steps);
    EXPECT_NEAR(total(steps), before, 1e-9);
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_GE(steps[k].score, 0.0);
      EXPECT_LE(steps[k].score, steps[k].max_score);
    }
  }
}

}  // namespace
}  // namespace pt::grader
