// The grader's instructor-only commands: `grader mutants` (the bug catalogue graded),
// `grader false-failures` (correct code re-rendered under many seeds) and `grader
// second-solution` (the second correct solution made and graded). None exists in a handout.
#pragma once

#include <CLI/CLI.hpp>

#include "grader/grade.h"

namespace pt::grader {

/// Adds the three subcommands to the grader's command line; after parsing, `chosen()` says
/// whether one was asked for and `run()` runs it.
class InstructorCommands {
 public:
  explicit InstructorCommands(CLI::App& app);

  bool chosen() const;
  /// Runs the chosen command with the grader's paths; returns the exit code (0 all as it
  /// should be, 1 something to look at, 2 the command could not run).
  int run(const GradeOptions& grade, const std::string& grader_exe) const;

 private:
  CLI::App* mutants_ = nullptr;
  CLI::App* false_failures_ = nullptr;
  CLI::App* second_ = nullptr;
  std::vector<std::string> only_;
  int jobs_ = 1, build_jobs_ = 2, seeds_ = 100, first_ = 1, part_ = 0;
  bool no_isolated_ = false, report_only_ = false;
  std::string work_, index_, log_, solution_ = "both";
};

}  // namespace pt::grader
