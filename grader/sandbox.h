// Where and how the grader runs the student's code (probes, renders, the student's build): as an
// unprivileged user of its own, in a fresh scratch folder, under limits. What the code gives back
// is only data for the grader's own judges (grader/judged_tests.h).
#pragma once

#include <string>
#include <vector>

#include "grader/process/child_process.h"

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
  /// How many probes may run at once (run_judged_tests): the k-th runs as uid + k, gid + k, so
  /// that ending one probe's processes (every process of its uid) never ends another's.
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

/// The tests of a GoogleTest executable as Suite.Name, from --gtest_list_tests. Only a program
/// with no student code in it (a judge) may be listed this way: a student's code runs before
/// main and could print any list.
std::vector<std::string> list_gtest_tests(const std::string& executable, double wall_seconds);

/// Reads the file a render wrote in a scratch folder only if it is what the sandbox's user made
/// there: a regular file (not a symbolic link), one link, owned by that user when the sandbox
/// protects. Returns "" when it is fine, else why not.
std::string check_scratch_output(const std::string& path, const Sandbox& sandbox);

}  // namespace pt::grader
