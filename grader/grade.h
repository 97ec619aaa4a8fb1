// Grading one part step by step: build it, run its step tests, render its scenes and compare
// them with references, and score each step on its own checks.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "grader/manifest.h"
#include "grader/sandbox.h"

namespace pt::grader {

/// The outcome of one check (a test or a render) of a step.
struct CheckResult {
  std::string name;       ///< partN.stepK.suite.test or partN.stepK.render.SCENE
  std::string kind;       ///< "test" or "render"
  bool pass = false;
  /// Not counted: the check could not run here (a course scene that is not there); `output`
  /// says why and what to do. Never a verdict on the code, and never in the bundle.
  bool skipped = false;
  std::string output;     ///< what a student reads: what failed, with its values, and the rule
  double seconds = 0.0;
  uint64_t seed = 0;      ///< of a render
  std::string todo;       ///< the "not implemented" lines the student's code printed (a few, short)
};

/// One step's score: its points shared equally among its counted checks.
struct StepResult {
  int part = 0, step = 0;
  std::string name;       ///< partN.stepK.NAME
  double score = 0.0, max_score = 0.0;
  std::vector<CheckResult> checks;
  std::string message;    ///< the first failing check and its message, or why nothing counted
  bool passed() const { return score >= max_score && counted() > 0; }
  int counted() const;
  int failed() const;
  int skipped() const;
  /// What the skipped checks would have weighed had they run (the step's points are shared among
  /// the checks that ran, so this much of the step was graded on fewer checks; all of it when
  /// none ran).
  double skipped_points() const;
};

/// One part's grade: whether it built, and its steps in order.
struct PartResult {
  int part = 0;
  bool built = true;
  std::string build_output;   ///< the build's error excerpt when it failed
  std::string rests_on;       ///< the one line on the earlier parts its renders run ("" if none)
  std::vector<StepResult> steps;
  std::vector<std::string> unassigned;  ///< tests whose name names no step of the manifest
  /// How Gradescope's figure for this part relates to this one. Gradescope grades each part with
  /// the course's complete solution of the other parts (as --isolated does), so a failing check
  /// that here ran another part of the student's that fails may pass there.
  bool graded_alone = false;            ///< graded as Gradescope grades it (--isolated, the bundle)
  int open_checks = 0;                  ///< failing checks that ran a failing earlier part
  double open_points = 0.0;             ///< their points: Gradescope gives at most this much more
  std::vector<int> failing_parts_run;   ///< those earlier parts
  /// Earlier parts its renders run whose record says they fail but whose files changed since they
  /// were graded: the range above is of the old code until they are graded again.
  std::vector<int> changed_parts_run;
  double seconds = 0.0;
  std::string files;                    ///< folder_fingerprint of the part's files as graded
  double score() const;
  double max_score() const;
  int failing_steps() const;
  int skipped_checks() const;
  double skipped_points() const;
};

/// Where things are and what to do.
struct GradeOptions {
  std::string source_dir;     ///< the project (scenes and references are relative to it)
  std::string build_dir;      ///< a configured CMake build tree of it
  std::string manifest_path;  ///< reference/manifest.json unless told otherwise
  std::string pathtracer;     ///< the renderer to run (the isolated one is found beside it)
  std::string out_dir = "grader-out";  ///< renders, diff images, JUnit XML, state.json go here
  bool build = true;          ///< build the part's targets first
  bool run_tests = true;      ///< run the part's step tests
  /// Link every other part's complete solution (the build's grade_partN_isolated): only part
  /// N's code is graded. `isolated_separate` says the solution is a copy apart from this tree
  /// (PT_SOLUTION_DIR); otherwise this tree is the solution and the ordinary targets are it.
  bool isolated = false;
  bool isolated_separate = false;
  int64_t seed_offset = 0;    ///< every graded render uses seed + seed_offset
  /// When set (the Gradescope bundle), the student's code runs in it: each test's probe, and
  /// each render as its user in a scratch folder, compared only if its variance is plausible.
  /// Else as the grader's own user (a developer's machine: nothing is protected).
  const Sandbox* sandbox = nullptr;
  /// The build tree whose judge programs decide the tests (the bundle's private one, built from
  /// the complete solution); empty: build_dir's own.
  std::string judge_build_dir;
  /// When set, every graded render is of a scene variant drawn for this grading (camera, lights:
  /// grader/scene_variant.h) and its reference is rendered at grading time by this renderer (the
  /// complete solution, which the student's user can neither read nor run), with `variant_key`.
  /// Empty: the manifest's references of the scenes as they are.
  std::string reference_renderer;
  uint64_t variant_key = 0;
  /// The bundle ships every scene it grades with: there a check that cannot run is the grader's
  /// own error (grade_part throws), never a skip.
  bool skip_is_error = false;
  /// When not empty (the bundle: stub_messages, grader/handout.h), the only lines of the
  /// student's output a message may quote: a line equal to one of the handout's own stub
  /// messages. Nothing else the student's code prints reaches the results.
  std::set<std::string> stub_messages;
  /// How many of the student's values (grader/student_values.h) the results of this grading may
  /// still quote: one count for every part a results file holds. Null: kValuesPerResults a part.
  int* quote_budget = nullptr;
};

/// Every step of `part`. Never throws for a student's failure: a crash, a hang or garbage is
/// that check's failure. Throws when a check could not run and options.skip_is_error.
PartResult grade_part(const Manifest& manifest, int part, const GradeOptions& options);

/// The student's earlier parts a part's renders run, as last graded (OUT/state.json).
struct EarlierParts {
  std::vector<int> failing;  ///< failed (or did not build) when last graded
  std::vector<int> unknown;  ///< not graded yet, or changed since they were
};

/// The line a failing render's message ends with: the state of the earlier steps of its part it
/// rests on (check.rests_on_steps), from their tests' {failed, counted} by step number, and of
/// the earlier parts it runs. It says "look first at this step's code" only when none of them is
/// known to fail.
std::string render_rests_on_line(const PartSpec& spec, const RenderCheck& check,
                                 const std::vector<std::pair<int, int>>& tests_failed_of,
                                 const EarlierParts& parts = {});

/// The state of the student's earlier parts that part `part`'s renders run (none when
/// options.isolated: the complete solution stands in for them).
EarlierParts earlier_parts(const Manifest& manifest, int part, const GradeOptions& options);

/// Renders one check as the grader does and compares it with its reference. The numbers of its
/// output that the student's render decided are marked (mark_values, grader/student_values.h):
/// release_values shows them.
CheckResult grade_render(const Manifest& manifest, const RenderCheck& check,
                         const GradeOptions& options);

/// Renders `check`'s reference of `scene` with `renderer` (its reference_args, reference_runs
/// seeds from reference_seed, their mean when more than one) into `out`; adds the time taken to
/// `seconds`. Returns "" or why it failed.
std::string render_reference(const RenderCheck& check, const std::string& renderer,
                             const std::string& scene, const std::string& out, double* seconds,
                             bool verbose);

/// Scores a step from its checks: points shared among the counted ones, the first failure's
/// message, and the "not implemented" lines of its stubs.
StepResult score_step(const StepSpec& spec, std::vector<CheckResult> checks);

/// The one line saying what part `part`'s renders rest on and the state of those parts when
/// they were last graded (OUT/state.json), or "" when they rest on nothing.
std::string rests_on_line(const Manifest& manifest, int part, const GradeOptions& options);

/// Fills `result`'s view of Gradescope's figure: which of its failing checks ran an earlier
/// part of the student's that fails (OUT/state.json), and their points.
void compare_with_gradescope(const Manifest& manifest, PartResult& result,
                             const GradeOptions& options);

/// A fingerprint of the content of every file under `folder` (names and bytes, XXH3, in hex):
/// how state.json tells a part's files from those it was graded on. Content, not modification
/// times, which are whole seconds on some file systems and come back with an undo.
std::string folder_fingerprint(const std::string& folder);

/// Records `result` in OUT/state.json for the next rests_on_line, with its files' fingerprint.
void record_state(const PartResult& result, const GradeOptions& options);

/// Renders the references of `part` (every part when 0) with the complete solution and records
/// in the manifest how each was made. Returns false (having said why on stderr) on a failure.
bool make_references(const Manifest& manifest, int part, const GradeOptions& options);

/// The lines of `output` that say something is not implemented yet, each once.
std::string not_implemented_lines(const std::string& output,
                                  const std::set<std::string>& only = {});

/// Whether the CMake build tree `build_dir` was configured with a solution apart from its own
/// sources (PT_SOLUTION_DIR), so that it has separate isolated targets; nothing when its
/// CMakeCache.txt cannot be read. A grader graded another tree than its own (a mutant's scratch
/// copy, by --build) must ask that tree, not the tree it was compiled in.
std::optional<bool> has_separate_solution(const std::string& build_dir);

/// The most a check's time limit is stretched for a busy machine.
constexpr double kMaxLoadFactor = 8.0;

/// A check's wall-time limit on a machine shared with other work: `seconds` (what it is given on
/// an idle machine) times the machine's load per core over the last minute, between 1 and
/// kMaxLoadFactor. Correct code on a busy machine is then not failed for time the machine did not
/// give it (a render's wall time grows with the load on its cores), and an endless loop still
/// ends.
double load_scaled_limit(double seconds, double load_average, int cores);

/// The same at this machine's load average now (`seconds` itself when it cannot be read).
double load_scaled_limit(double seconds);

/// A CMake build tree's cached value of `key` ("" when it has none); nothing when its
/// CMakeCache.txt cannot be read.
std::optional<std::string> cmake_cache_value(const std::string& build_dir, const std::string& key);

/// Why the build tree cannot grade Part 5 under the manifest's stopping rule (it was configured
/// for the other one: its tests and the renderer's default hold the other rule), or "".
std::string stopping_rule_mismatch(const Manifest& manifest, const std::string& build_dir);

}  // namespace pt::grader
