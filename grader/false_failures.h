// The false-failure measurement: every graded render of correct code re-rendered with many seeds
// and compared with its reference as the grader does, counting how often correct code fails.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "grader/grade.h"
#include "grader/manifest.h"

namespace pt::grader {

/// One graded render of one solution under one seed, as the log keeps it.
struct SeedRun {
  std::string solution;  ///< "complete" or "second"
  std::string render;    ///< the check's name
  long seed = 0;
  bool pass = false;
  double seconds = 0.0;
  std::string message;   ///< the comparison's first line when it failed
};

/// Options of `grader false-failures`.
struct FalseFailureOptions {
  int seeds = 100;        ///< seeds per render and solution
  int first = 1;          ///< the first seed offset (the graded seed is the manifest's + offset)
  int part = 0;           ///< only this part's renders (0: every part)
  std::vector<std::string> only;       ///< only renders whose name contains one of these
  std::vector<std::string> solutions = {"complete", "second"};
  std::string work_dir;   ///< the second solution's scratch tree and the renders
  std::string log_path;   ///< every run appended as a line; the table is made from it
  bool report_only = false;  ///< print the table from the log, render nothing
  int build_jobs = 2;
};

/// Runs the measurement, appending each seed's result to the log as it finishes; seeds the log
/// already holds are not run again, so the same command finishes an interrupted run. The next
/// render is always the (solution, render) that has had the least time, so each gets an equal
/// share of the machine. Returns this run's results.
std::vector<SeedRun> run_false_failures(const Manifest& manifest, const GradeOptions& grade,
                                        const FalseFailureOptions& options, std::ostream& log);

/// Reads the log (a missing log is empty); a malformed line is named and skipped.
std::vector<SeedRun> read_seed_log(const std::string& path, std::ostream& log);

/// One row a (render, solution): seeds, failures, the rate, the chance of as many failures or
/// more were the rate alpha, and a verdict against the manifest's family-wise alpha. Where a
/// seed was run more than once the last run counts.
void print_false_failure_table(std::ostream& out, const Manifest& manifest,
                               const std::vector<SeedRun>& runs);

/// P(X >= k) for X ~ Binomial(n, p).
double binomial_tail(int n, int k, double p);

}  // namespace pt::grader
