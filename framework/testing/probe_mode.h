// Not needed for the assignment.
// Whether this test program is a grader's probe (grader/judge/record.h): a run that only gathers
// what the graded code answers, for a judge in another process to decide on. A probe's own
// verdicts count for nothing, so a test may skip computing its expectations there (an exact or
// brute-force answer costs as much as the judge's run of the same test); it must make the same
// calls into the graded code, in the same order, either way, or the judge's replay fails.
#pragma once

namespace pt::test {

/// True in a probe (set by its main before any test runs), false in every other test program.
bool is_probe();
/// The probe's main says so.
void set_probe();

}  // namespace pt::test
