// Part 5, step 1 (convergence) under the stopping rule the assignment does not ask for: not
// graded (label stress), so that the instructor's CI keeps the other rule's cases, and the
// complete solution under that rule, working for the day the manifest switches rules.
#include <gtest/gtest.h>

#include "parts/5-adaptive/tests/convergence_cases.h"

namespace pt {
namespace {

TEST(convergence_other_rule, rule_on_hand_computed_cases) {
  test::convergence::rule_on_hand_computed_cases(
      kAssignmentStoppingRule == StoppingRule::course ? StoppingRule::split : StoppingRule::course);
}

// A hint names a mistake only when the answers are that mistake's alone: under either rule the
// hand-computed cases give every catalogued mistake answers of its own, none the right ones.
TEST(convergence_cases, tell_every_mistake_apart) {
  for (StoppingRule rule : {StoppingRule::split, StoppingRule::course}) {
    const std::vector<test::convergence::Case> cases = rule == StoppingRule::course
                                                           ? test::convergence::course_rule_cases()
                                                           : test::convergence::split_rule_cases();
    std::vector<std::vector<bool>> answers;
    std::vector<bool> right;
    for (const test::convergence::Case& c : cases) right.push_back(c.converged);
    for (const test::convergence::Mistake& m : test::convergence::mistakes(rule)) {
      std::vector<bool> a;
      for (const test::convergence::Case& c : cases)
        a.push_back(m.rule(c.decision, c.estimate_count, c.tolerance));
      EXPECT_NE(a, right) << m.cause << ": gives every right answer";
      for (size_t k = 0; k < answers.size(); ++k)
        EXPECT_NE(a, answers[k]) << m.cause << ": the same answers as mistake " << k;
      answers.push_back(a);
    }
  }
}

}  // namespace
}  // namespace pt
