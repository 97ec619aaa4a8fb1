// Part 5, step 1 (convergence): the stopping rule on hand-computed cases, shaped as the
// assignment's rule hands them over (convergence_cases.h). Where the answers are wrong, the test
// names the mistake whose rule gives exactly the answers it got, if one does.
#include <gtest/gtest.h>

#include "parts/5-adaptive/tests/convergence_cases.h"

namespace pt {
namespace {

TEST(convergence, rule_on_hand_computed_cases) {
  test::convergence::rule_on_hand_computed_cases(kAssignmentStoppingRule);
}

}  // namespace
}  // namespace pt
