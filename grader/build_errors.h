// What the results say of a build that failed. A compiler's error quotes the code it rejects, and
// a #error, a static_assert, an identifier or a #line directive puts any text the student chose
// into it, so its words are never quoted: only where each of the first errors is (a file of the
// project, a line and a column, each bounded) and what kind of error it is, in the grader's own
// words (docs/grading.md, "What reaches the student"). The student's own build shows the rest.
#pragma once

#include <string>

namespace pt::grader {

/// The errors a failed build's output shows at most, and the largest line and column quoted.
constexpr int kBuildErrorsShown = 2;
constexpr long kBuildLineShown = 99999;
constexpr long kBuildColumnShown = 999;

/// The compiler's and linker's `output` of a failed build of the project at `project` (whose
/// absolute paths the compiler wrote), as the results may say it: the first kBuildErrorsShown
/// errors, each as "FILE:LINE:COLUMN: KIND" (FILE a file of the project, else "a file"; LINE and
/// COLUMN only up to their bounds; KIND one of the grader's words for what the compiler said),
/// then how many errors there were (up to "more than 99"), then where to read them whole.
std::string build_errors(const std::string& output, const std::string& project);

}  // namespace pt::grader
