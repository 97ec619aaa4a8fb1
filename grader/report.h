// The results of a grading run: the score table a person reads and the Gradescope JSON.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grader/grade.h"

namespace pt::grader {

/// Prints each check with its points and pass/fail, its message under a failure, and totals.
void print_score_table(std::ostream& out, const std::vector<CheckResult>& results);

/// The Gradescope autograder results: {"score", "execution_time", "tests": [{"name", "score",
/// "max_score", "output", "visibility"}]}.
nlohmann::json gradescope_results(const std::vector<CheckResult>& results, double seconds);

/// Checks `j` against that documented shape; returns "" when it fits, else what does not.
std::string validate_gradescope(const nlohmann::json& j);

/// Whether every counted check passed with full marks.
bool all_passed(const std::vector<CheckResult>& results);

}  // namespace pt::grader
