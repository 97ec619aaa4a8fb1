// The step at fault: a check that fails while another step it runs fails is charged to that
// step, so that a bug costs points where it is and the total stays what the checks give.
#pragma once

#include <string>
#include <vector>

#include "grader/grade.h"
#include "grader/manifest.h"

namespace pt::grader {

/// The other steps of its part that a check of `spec` runs: a render's `rests_on_steps` (earlier
/// ones), a test's step's `tests_rest_on_steps` (usually earlier; Part 4's path tests compare
/// with the student's own step 2).
std::vector<int> check_rests_on(const StepSpec& spec, const CheckResult& check);

/// Moves the share of every failing check that rests on another step of its part with
/// failing checks of its own (for a later step: failing checks that do not run the check's step)
/// to the earliest such step, at most what that step has left
/// (its score never goes below 0; what it cannot take stays where the check is). The part's
/// total never changes, so no submission can raise its score by breaking a step on purpose.
/// Each step's message says what it was charged and for which checks, or what was charged away.
/// `steps` are the part's scored steps, in order, as score_step made them.
void charge_steps_at_fault(const PartSpec& spec, std::vector<StepResult>& steps);

}  // namespace pt::grader
