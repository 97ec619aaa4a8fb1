// Where and how the grader runs the student's code (probes, renders, the student's build): as an
// unprivileged user of its own, in a fresh scratch folder, under limits. What the code gives back
// is only data for the grader's own judges (grader/judged_tests.h).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grader/process/child_process.h"

namespace pt::grader {

/// The uids the student's processes run as: slot s owns the kUidsPerSlot uids from
/// kFirstStudentUid + s * kUidsPerSlot, and a grader holds its slot alone (a lock), so graders
/// side by side never share a uid. Below 65534, so that a container mapping 65536 uids has them.
constexpr long kFirstStudentUid = 60000, kUidsPerSlot = 64, kSlots = 80;
/// The supplementary group every student's process runs in: the group the deny ACLs of the shared
/// writable folders name where namespaces are refused (no account is needed for it).
constexpr long kStudentGroup = 59999;

struct SandboxState;

/// The users, the scratch folders and the limits the student's processes get. Each process
/// (each make_scratch ... finish) runs as a uid of its own, and leaves nothing behind: with
/// namespaces, it gets mount, IPC and network namespaces and an empty tmpfs over every folder
/// its user could otherwise write; where they are refused (Docker's default seccomp profile, or
/// PT_SANDBOX_NAMESPACES=off), its user can write no folder but its scratch (a deny ACL on every
/// shared writable folder), a seccomp filter refuses SysV IPC, POSIX message queues and
/// sockets, and after it every file and IPC object of its uid is removed and checked gone.
struct Sandbox {
  /// The first uid of this sandbox's slot; -1: the grader's own user (a developer's machine
  /// without root). Then nothing stops the student's code from reading what the grader reads:
  /// the results say "unprotected".
  long uid = -1, gid = -1;
  std::string scratch_root;  ///< each run gets a fresh folder below it, the only one it may write
  ChildLimits limits;        ///< wall_seconds is set per run from the check's own limit
  double max_check_seconds = 0.0;  ///< when > 0, caps every run's wall time (CI's cheater runs)
  /// How many probes may run at once (run_judged_tests), each as a uid of its own.
  int jobs = 1;
  /// The student's processes get namespaces of their own (else the refused-namespaces way).
  bool namespaces = false;
  /// The slot's lock and which of its uids are in use, shared by the copies (lanes) of a sandbox.
  std::shared_ptr<SandboxState> state;

  bool protects() const { return uid >= 0; }

  /// The same sandbox for one of the tests run at once: its processes still take their uids
  /// from the one slot.
  Sandbox lane(int k) const;

  /// The sandbox the grader uses by default: as root, the first free slot from `slot` on (taken
  /// with a lock until the last copy of the sandbox goes), namespaces where the kernel gives
  /// them and PT_SANDBOX_NAMESPACES is not "off", the given limits; otherwise the caller's user,
  /// unprotected. `scratch_root` is made (0711, root's) if missing. Throws when no slot is free
  /// or a shared folder cannot be kept from the student's user.
  static Sandbox standard(const std::string& scratch_root, int slot = 0);

  /// A fresh scratch folder for one run, owned by a uid of its own (free in the slot), mode 0700.
  std::string make_scratch(const std::string& name) const;

  /// The uid (and gid) the run in `scratch` goes as; the sandbox's `uid` when unprotected.
  long uid_of(const std::string& scratch) const;

  /// Removes a run's scratch folder and, under a uid of its own, every file and IPC object that
  /// uid left in the machine's shared places, then checks they are gone (what is not is kept for
  /// leftovers()) and frees the uid.
  void finish(const std::string& scratch) const;

  /// What any run of this sandbox left that could not be removed; "" when nothing. A grading
  /// with leftovers is the grader's error, not a verdict.
  std::string leftovers() const;

  /// What run_child needs to run one command here: the limits (with `wall_seconds`), the run's
  /// user, its confinement (`scratch` the one folder it writes), `scratch` as working folder, HOME
  /// and TMPDIR pointing at it.
  ChildOptions options(const std::string& scratch, double wall_seconds) const;
};

/// Runs `work` in a child of this process that is user `uid` (group `uid`, and the students'
/// group kStudentGroup) and returns what it returned: what that user can read or write, asked
/// without an exec. Throws when the child cannot become the user or does not end well.
std::string as_student_user(long uid, const std::function<std::string()>& work);

/// Whether this process can give a child mount, IPC and network namespaces (root, and no seccomp
/// profile refusing them). Asked once.
bool kernel_gives_namespaces();

/// The tests of a GoogleTest executable as Suite.Name, from --gtest_list_tests. Only a program
/// with no student code in it (a judge) may be listed this way: a student's code runs before
/// main and could print any list.
std::vector<std::string> list_gtest_tests(const std::string& executable, double wall_seconds);

/// Reads the file a render wrote in a scratch folder only if it is what the sandbox's user made
/// there: a regular file (not a symbolic link), one link, owned by the scratch folder's user when
/// the sandbox protects. Returns "" when it is fine, else why not.
std::string check_scratch_output(const std::string& path, const Sandbox& sandbox);

}  // namespace pt::grader
