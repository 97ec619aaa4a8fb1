// The results of a grading run: the score table a person reads and the Gradescope JSON.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grader/grade.h"

namespace pt::grader {

/// What the run was, for the JSON's extra_data.
struct RunInfo {
  bool isolated = false;
  int64_t seed_offset = 0;
  double seconds = 0.0;
};

/// Prints, per part, the line on the parts its renders rest on, then one row per step (step,
/// points, pass/FAIL, checks) with the first failing check and its message under a failure, and
/// the total.
void print_score_table(std::ostream& out, const std::vector<PartResult>& results);

/// The line under the total when checks could not run: how many, and what they would have
/// weighed (graded on their steps' other checks instead).
std::string skipped_summary(int checks, double weight);

/// Gradescope's autograder results, one test per step (docs/grading.md): {"score",
/// "execution_time", "output", "tests": [{"name", "number", "score", "max_score", "status",
/// "output", "visibility", "extra_data": {"checks": [...]}}], "extra_data"}.
nlohmann::json gradescope_results(const std::vector<PartResult>& results, const RunInfo& info);

/// Checks `j` against that documented shape; returns "" when it fits, else what does not.
std::string validate_gradescope(const nlohmann::json& j);

/// Whether every step of every part has full marks.
bool all_passed(const std::vector<PartResult>& results);

}  // namespace pt::grader
