// The mutant run: each catalogued bug (grader/mutants/) applied to a scratch copy of the complete
// solution, the part it belongs to graded, and whether it lost points in its own step only, with
// a message that names its cause.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grader/manifest.h"

namespace pt::grader {

/// One catalogued bug: its patch and what grading it must show.
struct MutantSpec {
  std::string name;   ///< "21-albedo-over-2pi"
  std::string patch;  ///< the patch file, relative to the index's folder
  int part = 0;
  std::string step;   ///< the one step it must lose points in, "part3.step1.diffuse_bsdf"
  std::string bug;    ///< what the patch does
  std::string cause;  ///< what a true hint says
  std::string hint;   ///< a regular expression (case-insensitive) a true hint matches
};

/// Reads the catalogue's index (grader/mutants/index.json); throws std::runtime_error naming
/// the file and the entry when it is malformed.
std::vector<MutantSpec> read_mutant_index(const std::string& path);

/// Points a grading run took away from one step, and its message.
struct StepLoss {
  std::string step;
  double lost = 0.0, max_score = 0.0;
  std::string message;
};

/// What grading one mutant showed.
struct MutantOutcome {
  MutantSpec spec;
  std::string verdict;  ///< "ok", "hint?", "OVERFLOW", "PASSES", "ALSO ELSEWHERE", "WRONG STEP", "BUILD", "ERROR"
  std::vector<StepLoss> losses;  ///< every step that lost points
  std::string message;           ///< the own step's message (else the first loss's, or the error)
  double seconds = 0.0;
};

/// The steps that lost points in a grader's JSON results (one test per step, as
/// docs/grading.md has it; a results file of per-check tests, partN.tests with its
/// "failed: partN.stepK.suite.test" lines and one test per render, is read too, each failing
/// test's share given to its step and each render under its own name).
std::vector<StepLoss> step_losses(const nlohmann::json& results);

/// The verdict on a mutant from the steps that lost points: "ok" when only its own step did and
/// the message matches its hint, "hint?" when only its own step did but the message does not
/// name the cause, "PASSES" when nothing did, "ALSO ELSEWHERE" / "WRONG STEP" otherwise, and
/// "RENDERS ONLY" when only checks named by no step (renders of a per-check grader) lost;
/// "OVERFLOW" when its own step lost every point and the rest stayed in steps whose messages
/// name its step as the one at fault (the bug costs more than its step is worth).
MutantOutcome judge_mutant(const MutantSpec& spec, const std::vector<StepLoss>& losses);

/// Options of `grader mutants`.
struct MutantRunOptions {
  std::string source_dir;     ///< the instructor's project (never changed)
  std::string index_path;     ///< grader/mutants/index.json unless told
  std::string work_dir;       ///< scratch trees and results: BUILD/mutants unless told
  std::string grader_exe;     ///< the grader to run on each copy (this one)
  std::vector<std::string> only;  ///< names (or fragments) to run, in this order; all when empty
  int jobs = 1;               ///< mutants graded at once, each in its own scratch tree
  int build_jobs = 2;         ///< -j of each build
  bool isolated = true;       ///< pass --isolated when the grader has it
  bool report_only = false;   ///< grade nothing: judge the results an earlier run left
};

/// Runs the catalogue; prints progress to `log` and returns each mutant's outcome in index order.
std::vector<MutantOutcome> run_mutants(const MutantRunOptions& options, std::ostream& log);

/// Per rule of the manifest: each mutant that breaks it, its verdict, and whether its step's
/// message names the rule (its `#id`), so a hint is seen to name the rule the code broke.
void print_rule_table(std::ostream& out, const Manifest& manifest,
                      const std::vector<MutantOutcome>& outcomes);

/// The table: mutant, the step it must lose in, where it lost (points), verdict, message.
void print_mutant_table(std::ostream& out, const std::vector<MutantOutcome>& outcomes,
                        double seconds);

}  // namespace pt::grader
