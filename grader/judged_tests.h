// A part's step tests as the grader runs them: each test twice, first as a probe that runs the
// student's code and only records what its functions gave (in the sandbox, as the student's
// user), then as a judge that holds no student code, replays that record and decides
// (grader/judge/record.h). The verdict and its message come from the judge alone; of what the
// student's code printed, only its "not implemented" lines reach the student, a few and short.
#pragma once

#include <string>
#include <vector>

#include "grader/sandbox.h"

namespace pt::grader {

/// One step test: its name as the manifest's steps know it, and its two programs.
struct JudgedTest {
  std::string name;   ///< partN.stepK.Suite.Test
  int part = 0, step = 0;
  std::string probe;  ///< the test program with the student's part, recording
  std::string judge;  ///< the test program that replays the record and decides
  std::string gtest;  ///< Suite.Test
};

/// Whether `build_dir` has the probes and judges of part `part` (a platform whose linker cannot
/// make probes has none: the grader then decides from the test programs, grader/grade.cpp).
bool has_judges(const std::string& build_dir, int part);

/// The step tests of part `part`, listed from its judge programs under `judge_build` (they hold
/// no student code, so their list can be trusted), with the probes under `probe_build`.
std::vector<JudgedTest> list_judged_tests(int part, const std::string& probe_build,
                                          const std::string& judge_build);

/// How one judged test went.
struct JudgedOutcome {
  bool pass = false;
  /// The judge skipped the test (GTEST_SKIP before any call into the part: a course scene it
  /// needs is not there); `message` is its reason. Decided by the judge, never by the probe.
  bool skipped = false;
  bool disk_exceeded = false;  ///< the probe was stopped for the disk (tests beside it share it)
  bool killed_from_outside = false;  ///< the probe was killed by no limit of its own
  std::string message;         ///< the judge's failure, then what the probe's ending says
  std::string student_output;  ///< what the probe printed (for its "not implemented" lines)
  double seconds = 0.0;
};

/// The reason a GoogleTest run printed for its first skipped test (the lines after "Skipped" up
/// to the next status line), or "" when nothing was skipped.
std::string gtest_skip_reason(const std::string& output);

/// Runs every test of `tests`, each probe then judge, up to sandbox.jobs at once (each lane a
/// uid of its own), outcomes in the order of `tests`. A probe stopped for the disk while others
/// ran beside it runs again alone, and so does one killed from outside (by no limit of its own);
/// killed from outside again, it is the grader's error (std::runtime_error), never a verdict. `work_dir` is the grader's own folder for the records.
/// `expected_seconds` (empty, or one per test: what each took last time) starts the longest
/// first, so that no lane is left with a long test at the end while the others wait.
std::vector<JudgedOutcome> run_judged_tests(const std::vector<JudgedTest>& tests,
                                            const Sandbox& sandbox, double wall_seconds,
                                            const std::string& work_dir,
                                            const std::vector<double>& expected_seconds = {});

}  // namespace pt::grader
