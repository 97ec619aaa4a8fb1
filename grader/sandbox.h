// Where and how the grader runs the student's code (tests, renders, the student's build): as an
// unprivileged user of its own, in a fresh scratch folder, under limits, with the test outcomes
// read from a sealed report instead of an exit code or printed lines.
#pragma once

#include <string>
#include <vector>

#include "framework/process/child_process.h"

namespace pt::grader {

/// The user, the scratch folders and the limits the student's processes get.
struct Sandbox {
  /// The user and group the student's processes run as; -1: the grader's own (a developer's
  /// machine without root). Then nothing stops the student's code from reading what the grader
  /// reads: the results say "unprotected".
  long uid = -1, gid = -1;
  std::string scratch_root;  ///< each run gets a fresh folder below it, the only one it may write
  ChildLimits limits;        ///< wall_seconds is set per run from the check's own limit
  double max_check_seconds = 0.0;  ///< when > 0, caps every run's wall time (CI's cheater runs)
  /// How many tests may run at once (run_sealed_tests): the k-th runs as uid + k, gid + k, so
  /// that ending one test's processes (every process of its uid) never ends another's.
  int jobs = 1;

  bool protects() const { return uid >= 0; }

  /// The same sandbox as user uid + k (k < jobs): where the k-th of the tests run at once goes.
  Sandbox lane(int k) const;

  /// The sandbox the grader uses by default: as root, a uid of its own chosen from `slot`
  /// (60000 + slot; no account is needed for it), the given limits; otherwise the caller's user,
  /// unprotected. `scratch_root` is made (0711, root's) if missing.
  static Sandbox standard(const std::string& scratch_root, int slot = 0);

  /// A fresh scratch folder for one run, owned by the sandbox's user, mode 0700.
  std::string make_scratch(const std::string& name) const;

  /// Removes a run's scratch folder, and whatever the sandbox's user left in the shared temp
  /// folders (/tmp, /var/tmp, /dev/shm), so one check cannot fill the disk for the next.
  void finish(const std::string& scratch) const;

  /// What run_child needs to run one command here: the limits (with `wall_seconds`), the user,
  /// `scratch` as working folder, HOME and TMPDIR pointing at it.
  ChildOptions options(const std::string& scratch, double wall_seconds) const;
};

/// One test of a part as the complete solution's build registers it.
struct TrustedTest {
  std::string name;        ///< partN.stepK.suite.test (CTest's name, "isolated." removed)
  int part = 0, step = 0;
  std::string executable;  ///< its GoogleTest program in the build tree
  std::string gtest;       ///< its GoogleTest name, Suite.Name
};

/// A test's outcome as the grader counts it.
enum class SealedStatus { passed, failed, skipped };

struct SealedTest {
  std::string name;          ///< GoogleTest's Suite.Name
  SealedStatus status = SealedStatus::failed;
  bool disk_exceeded = false;  ///< stopped for using more disk than allowed
  std::string output;        ///< what the test printed (for the student's message)
  std::string why;           ///< when failed: why, in a student's terms
  double seconds = 0.0;
};

/// Runs the one test `name` of the GoogleTest executable `executable` in the sandbox
/// (--gtest_filter=name) with a report descriptor and a fresh nonce, and judges it by
/// judge_sealed_report.
SealedTest run_sealed_test(const std::string& executable, const std::string& name,
                           const Sandbox& sandbox, double wall_seconds,
                           const std::vector<std::string>& environment = {});

/// One test to run: its program, its GoogleTest name, its wall-time limit.
struct SealedRun {
  std::string executable;
  std::string name;
  double wall_seconds = 60.0;
};

/// Runs every test of `runs` as run_sealed_test does, up to sandbox.jobs at once (each lane a
/// uid of its own), and returns their outcomes in the order of `runs`. The disk limit watches
/// free space, which tests running side by side share: a test stopped for the disk while
/// another ran beside it is run again alone, and only that run's outcome counts.
std::vector<SealedTest> run_sealed_tests(const std::vector<SealedRun>& runs, const Sandbox& sandbox,
                                         const std::vector<std::string>& environment = {});

/// The verdict from a run's report and its ending: passed only when the report holds, with
/// `nonce`, exactly one line for `name` saying passed and the closing line of the program, no
/// line with another nonce, and the process exited with status 0; skipped only the same way
/// with a skip line. Anything else is a failure, `why` saying which rule failed.
SealedStatus judge_sealed_report(const std::string& report, const std::string& nonce,
                                 const std::string& name, const ChildResult& run,
                                 std::string* why);

/// 128 random bits as 32 hex digits (from the system's random device).
std::string draw_nonce();

/// The tests of a GoogleTest executable as Suite.Name, from --gtest_list_tests. Only the
/// instructor's build (the complete solution) may be listed this way: a student's code runs
/// before main and could print any list.
std::vector<std::string> list_gtest_tests(const std::string& executable, double wall_seconds);

/// Reads the file a render wrote in a scratch folder only if it is what the sandbox's user made
/// there: a regular file (not a symbolic link), one link, owned by that user when the sandbox
/// protects. Returns "" when it is fine, else why not.
std::string check_scratch_output(const std::string& path, const Sandbox& sandbox);

}  // namespace pt::grader
