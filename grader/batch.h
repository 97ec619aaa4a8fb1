// `grader batch DIR`: a course's grading without Gradescope. Every submission folder under DIR
// is graded the way the bundle's run_autograder grades one (the same intake, sandbox, limits and
// results), several at once within the machine's cores, each in a fresh copy of the set-up tree.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grader/autograde.h"

namespace pt::grader {

/// What to grade and where.
struct BatchOptions {
  std::string submissions;  ///< DIR: one folder per submission, its name the submission's
  std::string root;         ///< a root folder the bundle's setup.sh set up (its tree untouched)
  std::string out_dir;      ///< NAME/results.json and scores.csv; default DIR-results
  int jobs = 0;             ///< submissions graded at once (0: one per core)
  std::vector<int> parts;   ///< only these parts (empty: all)
  AutogradeTuning tuning;   ///< max_check_seconds and quote_student_lines go to every run
  std::string grader_exe;   ///< the grader to run each submission with
};

/// One row of scores.csv.
struct BatchScore {
  std::string submission;
  int part = 0;
  std::string step;  ///< partN.stepK.NAME
  double points = 0.0, max_points = 0.0;
};

/// The rows of one submission's results.json (one per step).
std::vector<BatchScore> scores_of(const std::string& submission, const nlohmann::json& results);

/// "submission,part,step,points,max_points" and one line per row (names quoted as CSV wants).
std::string scores_csv(const std::vector<BatchScore>& rows);

/// Grades every folder under options.submissions, prints one score line each, writes
/// OUT/NAME/results.json and OUT/scores.csv. Runs side by side only where this process can make
/// mount namespaces (root with CAP_SYS_ADMIN): each run gets a copy of the set-up tree mounted at
/// the tree's own path. Elsewhere one at a time, the tree restored from its copy before each.
/// Returns 0 when every submission has its results (a failed build is a result), 2 when the
/// batch cannot start (the root not set up, DIR missing).
int grade_batch(const BatchOptions& options);

}  // namespace pt::grader
