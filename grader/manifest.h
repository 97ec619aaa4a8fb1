// The grading manifest (reference/manifest.json), the one rubric: every part's steps in order,
// each with its points, its functions and its graded renders, and how each reference was made.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pt::grader {

/// One graded render: a scene rendered with given flags and compared with a reference.
struct RenderCheck {
  std::string name;                     ///< "part3.step4.render.cornell_gap"
  int part = 0, step = 0;
  std::string scene;                    ///< relative to the project (or to the course's scenes)
  bool course_scene = false;            ///< scene lies in ../shared/scenes/cs184: skipped if absent
  std::string kind;                     ///< normals, direct, hemisphere, path, adaptive: the hints
  std::vector<std::string> args;        ///< flags of the graded render
  std::vector<std::string> reference_args;  ///< flags of the reference render
  uint64_t seed = 0;                    ///< of the graded render
  uint64_t reference_seed = 0;          ///< of the reference: different random numbers
  double timeout = 60.0;                ///< seconds for the graded render
  double relative_tolerance = -1.0;     ///< of the comparison; < 0: the manifest's
  /// > 0: the render's per-sample variance must be within this factor of the reference's (made
  /// with the same estimator and per-sample settings), so that a render taking fewer light
  /// samples than -l asks for fails although its mean is right. 0: not checked.
  double noise_limit = 0.0;
  std::string reference;                ///< the reference EXR, relative to the project
  std::string checksum;                 ///< CRC-32 of the reference file, "" until it is made
  /// The earlier steps of its part whose functions the render runs besides its own step's (the
  /// manifest's `rests_on_steps`; every earlier step when it says nothing). A failing render's
  /// message gives their state.
  std::vector<int> rests_on_steps;
  /// Part 5: the stopping rule this render is graded under ("split" or "course"); empty for
  /// renders every assignment grades. A render of the other rule is kept (its reference stays
  /// made) but not graded.
  std::string stopping_rule;
  /// How many renders of reference_args (seeds reference_seed, reference_seed + 1, ...) the
  /// reference is the mean of: more than one where only a render with the graded settings has the
  /// graded render's expectation (the course's stopping rule is biased by design, so its
  /// reference is made with that rule at those settings, averaged to bring its noise down).
  int reference_runs = 1;

  /// Whether `seed` is one of the reference's own seeds (the same random numbers).
  bool is_reference_seed(uint64_t seed) const {
    return seed >= reference_seed && seed - reference_seed < uint64_t(reference_runs);
  }
};

/// One rule a step states (in its STUDENT comment or its part page): what must hold, not how to
/// code it; the checks that enforce it, and the catalogued bugs that break it alone.
struct Rule {
  std::string id;                       ///< "several_lights", unique in its step
  std::string text;                     ///< "every light adds its own light: a sum over the lights"
  std::vector<std::string> checks;      ///< test names (a parameterised test's name without /...) or renders
  std::vector<std::string> mutants;     ///< grader/mutants/index.json names

  /// "part3.step4.importance#several_lights"
  std::string full_name(const std::string& step_full_name) const { return step_full_name + "#" + id; }
};

/// One step of a part: what the student writes in it, its points and its renders. Its tests
/// are the CTest tests named `partN.stepK.*` (from parts/N-*/tests/stepK_NAME_test.cpp).
struct StepSpec {
  int part = 0, step = 0;
  std::string name;                     ///< "importance"
  std::string title;                    ///< what the step is, in a few words
  double points = 0.0;
  std::vector<std::string> functions;   ///< "parts/3-direct/direct_lighting.cpp: estimate_direct_importance"
  std::string rests_on;                 ///< what its checks call besides its functions, in words
  /// The other steps of the part whose student functions its tests run (the manifest's
  /// `tests_rest_on_steps`; usually earlier ones): a failing test is charged to the earliest of
  /// them that fails (grader/step_at_fault.h).
  std::vector<int> tests_rest_on_steps;
  std::vector<RenderCheck> renders;     ///< graded under the manifest's stopping rule
  std::vector<RenderCheck> other_rule_renders;  ///< of the other stopping rule: not graded
  std::vector<Rule> rules;              ///< what the handout says must hold (grader rules)

  std::string full_name() const;        ///< "part3.step4.importance"
  std::string test_prefix() const;      ///< "part3.step4."
};

/// A part: its steps, its time limits, and the earlier parts its renders run.
struct PartSpec {
  int part = 0;
  std::string title;
  double test_timeout = 60.0;           ///< per test
  double build_timeout = 1200.0;
  std::vector<int> renders_rest_on;     ///< earlier parts whose student code its renders run
  /// Earlier parts whose student code its tests run where no complete solution stands in for
  /// them (a handout: Part 2's traversal tests meet Part 1's triangles in the leaves).
  std::vector<int> tests_rest_on;
  std::vector<StepSpec> steps;

  const StepSpec* find_step(int step) const;
  std::vector<const RenderCheck*> renders() const;  ///< the graded ones
  /// Also the renders of the other stopping rule (their references are made all the same).
  std::vector<const RenderCheck*> renders_of_every_rule() const;
  double points() const;
};

/// The whole manifest; `json` keeps what was read so that a rewrite keeps unknown fields.
struct Manifest {
  int block_size = 16;
  double alpha = 0.01;
  double relative_tolerance = 1e-5;     ///< of every render comparison (float rounding)
  double absolute_tolerance = 1e-6;
  std::string stopping_rule = "split";  ///< Part 5: "split" (the handout's) or "course"
  std::vector<PartSpec> parts;
  nlohmann::ordered_json json;

  const PartSpec* find_part(int part) const;
  const RenderCheck* find_render(const std::string& name) const;
};

/// Reads and checks the manifest; throws std::runtime_error naming the file and the entry.
Manifest read_manifest(const std::string& path);

/// Records how a reference was made (command, seconds, checksum) in the manifest file.
void record_reference(const std::string& manifest_path, const std::string& check_name,
                      const nlohmann::ordered_json& made);

/// CRC-32 of a file as 8 hex digits; throws std::runtime_error when it cannot be read.
std::string file_checksum(const std::string& path);

}  // namespace pt::grader
