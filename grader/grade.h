// Grading one part: build it, run its tests, render its scenes and compare them with references.
#pragma once

#include <string>
#include <vector>

#include "grader/manifest.h"
#include "grader/sandbox.h"

namespace pt::grader {

/// The outcome of one check, as the score table and the Gradescope results show it.
struct CheckResult {
  std::string name;
  int part = 0;
  double score = 0.0, max_score = 0.0;
  bool pass = false;
  bool skipped = false;   ///< not counted (a course scene that is not there)
  std::string output;     ///< what a student reads: what failed and what to look at
  double seconds = 0.0;
};

/// Where things are and what to do.
struct GradeOptions {
  std::string source_dir;     ///< the project (scenes and references are relative to it)
  std::string build_dir;      ///< a configured CMake build tree of it
  std::string manifest_path;  ///< reference/manifest.json unless told otherwise
  std::string pathtracer;     ///< the renderer to run
  std::string out_dir = "grader-out";  ///< renders, diff images and JUnit XML go here
  bool build = true;          ///< build the part's targets first
  bool run_tests = true;      ///< run the part's CTest label
  /// When set, renders run in it (as its user, in a scratch folder, under its limits) and their
  /// variance is checked against the reference's (the Gradescope bundle); else as the grader.
  const Sandbox* sandbox = nullptr;
};

/// Every check of `part`, in the order the table shows them. Never throws for a student's
/// failure: a crash, a hang or garbage is that check's failure.
std::vector<CheckResult> grade_part(const Manifest& manifest, int part, const GradeOptions& options);

/// Renders one check as the grader does and compares it with its reference.
CheckResult grade_render(const Manifest& manifest, const RenderCheck& check,
                         const GradeOptions& options);

/// Renders the references of `part` (every part when 0) with the complete solution and records
/// in the manifest how each was made. Returns false (having said why on stderr) on a failure.
bool make_references(const Manifest& manifest, int part, const GradeOptions& options);

/// The lines of `output` that say something is not implemented yet, each once.
std::string not_implemented_lines(const std::string& output);

}  // namespace pt::grader
