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

}  // namespace
}  // namespace pt
