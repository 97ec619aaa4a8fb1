// Runs one command as a child process with a time limit, so a crash or a hang fails one check.
#pragma once

#include <string>
#include <vector>

namespace pt::grader {

/// How a child ended, and what it printed (stdout and stderr together, in order).
struct ChildResult {
  int exit_code = -1;       ///< when it exited; -1 otherwise
  int signal = 0;           ///< the signal that ended it (SIGSEGV, ...), 0 when it exited
  bool timed_out = false;   ///< killed by us at the time limit
  bool started = true;      ///< false when the program could not be run at all
  double seconds = 0.0;
  std::string output;

  bool ok() const { return started && !timed_out && signal == 0 && exit_code == 0; }
  /// "exited with status 2", "crashed (SIGSEGV)", "ran past its 30 s limit", ...
  std::string describe() const;
};

/// Runs argv[0] (looked up on PATH) with `argv`, in `working_dir` when not empty, killing its
/// whole process group at `timeout_seconds`. Output beyond `max_output` bytes is cut (a child
/// that prints garbage forever must not fill the disk).
ChildResult run_child(const std::vector<std::string>& argv, double timeout_seconds,
                      const std::string& working_dir = {}, size_t max_output = 1 << 20);

/// The command as a person would type it (arguments with spaces quoted).
std::string command_line(const std::vector<std::string>& argv);

}  // namespace pt::grader
