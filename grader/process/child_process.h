// Runs one command as a child process under limits (wall and CPU time, memory, processes,
// output, file size, disk), optionally as another user, and ends its whole process tree when it
// ends, so a crash, a hang or a hostile program fails one check (the grader's) or one render
// (the write-up's) instead of stopping, or fooling, the tool that runs it.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace pt {

/// Where a child's standard error goes: into `output` with its standard output, in the order
/// they were printed (for a person to read), or into `errors` of its own (when stdout is data).
enum class ChildStreams { merged, separate };

/// Limits on a child and everything it starts. 0 means "no limit" for each.
struct ChildLimits {
  double wall_seconds = 60.0;    ///< the whole tree is killed at this time
  double cpu_seconds = 0.0;      ///< per process (RLIMIT_CPU): SIGXCPU, then SIGKILL
  size_t address_space = 0;      ///< bytes per process (RLIMIT_AS): allocations fail beyond it
  int processes = 0;             ///< processes of the child's user (RLIMIT_NPROC); only
                                 ///< enforced under a user of its own (root is exempt)
  size_t file_size = 0;          ///< bytes per file written (RLIMIT_FSIZE): SIGXFSZ beyond it
  size_t max_output = 1 << 20;   ///< bytes of each stream kept (the rest is cut)
  size_t disk_bytes = 0;         ///< the tree is killed once the file systems of `disk_watch`
                                 ///< have lost this many free bytes since it started
  std::vector<std::string> disk_watch;  ///< folders whose file systems are watched
};

/// What a child may leave for a later one, kept to nothing (Linux keeper only; docs/grading.md).
struct ChildConfinement {
  /// New mount, IPC and network namespaces: its SysV and POSIX IPC die with it, it has no
  /// network, and every folder of `cover` is an empty tmpfs of its own (or, when it holds a
  /// folder of `writable`, read-only with those folders writable inside).
  bool namespaces = false;
  std::vector<std::string> cover;     ///< folders (a file: made read-only) the child must not share
  std::vector<std::string> writable;  ///< folders that stay writable (its scratch, the build tree)
  /// A supplementary group to run in (the group the deny ACLs of shared folders name); -1: none.
  long group = -1;
  /// No POSIX message queues (RLIMIT_MSGQUEUE 0), and a seccomp filter that refuses SysV IPC and
  /// sockets: what no mount can take away where namespaces are refused.
  bool refuse_ipc_and_network = false;
};

/// How a child is run.
struct ChildOptions {
  ChildLimits limits;
  std::string working_dir;                 ///< empty: the caller's
  ChildStreams streams = ChildStreams::merged;
  /// Run as this user and group (setgid, setgroups({}), setuid before exec); -1 keeps the
  /// caller's. Needs root; refused (started = false) when the caller cannot switch.
  long uid = -1, gid = -1;
  /// NAME=VALUE entries added to (or replacing in) the caller's environment.
  std::vector<std::string> environment;
  /// Descriptors of the caller passed on to the child under the same number (a report pipe's
  /// write end); every other descriptor but 0, 1, 2 is closed.
  std::vector<int> keep_fds;
  ChildConfinement confinement;
};

/// How a child ended, and what it printed.
struct ChildResult {
  int exit_code = -1;       ///< when it exited; -1 otherwise
  int signal = 0;           ///< the signal that ended it (SIGSEGV, ...), 0 when it exited
  bool timed_out = false;   ///< killed by us at the wall-time limit
  bool disk_exceeded = false;  ///< killed by us for using more disk than allowed
  bool started = true;      ///< false when the program could not be run at all
  bool unknown_status = false;  ///< no wait status could be had: counted as a failure
  int descendants_killed = 0;   ///< processes it left behind that were ended with it
  /// Ended by a SIGKILL that no limit of its own sent (the Linux keeper only): the grader must
  /// run it again or call the run its own error, never score it.
  bool killed_from_outside = false;
  double seconds = 0.0;
  std::string output;       ///< stdout, and stderr too with ChildStreams::merged
  std::string errors;       ///< stderr with ChildStreams::separate; why, when it did not start

  bool ok() const {
    return started && !unknown_status && !timed_out && !disk_exceeded && signal == 0 &&
           exit_code == 0;
  }
  /// "exited with status 2", "crashed (SIGSEGV)", "ran past its 30 s limit", ...
  std::string describe() const;
};

/// Runs argv[0] (looked up on PATH) with `argv`, no shell in between, under `options`. The child
/// runs under a keeper process that is a child subreaper (PR_SET_CHILD_SUBREAPER): whatever the
/// child starts, even after setsid() or a double fork, stays below the keeper, and when the
/// child ends (or a limit is reached) the keeper kills and reaps every remaining descendant
/// (and, under a user of its own, every process of that user) before it reports. Built without
/// that keeper (PT_LINUX_SANDBOX off: every system but Linux), the child is a process group of
/// its own that is killed at its end: what leaves the group is not followed, and `uid`/`gid` are
/// refused (grader/process/posix_runner.cpp).
ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options);

/// The same with a wall-time limit only (the other limits off), the caller's user.
ChildResult run_child(const std::vector<std::string>& argv, double timeout_seconds,
                      const std::string& working_dir = {}, size_t max_output = 1 << 20,
                      ChildStreams streams = ChildStreams::merged);

/// The command as a person would type it (arguments with spaces quoted).
std::string command_line(const std::vector<std::string>& argv);

/// The last `lines` non-empty lines of a child's output, for an error message that stays
/// readable.
std::string tail_lines(const std::string& text, int lines);

}  // namespace pt
