// Runs one command as a child process with a time limit, so a crash or a hang fails one check
// (the grader's) or one render (the write-up's) instead of stopping the tool that runs it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pt {

/// Where a child's standard error goes: into `output` with its standard output, in the order
/// they were printed (for a person to read), or into `errors` of its own (when stdout is data).
enum class ChildStreams { merged, separate };

/// How a child ended, and what it printed.
struct ChildResult {
  int exit_code = -1;       ///< when it exited; -1 otherwise
  int signal = 0;           ///< the signal that ended it (SIGSEGV, ...), 0 when it exited
  bool timed_out = false;   ///< killed by us at the time limit
  bool started = true;      ///< false when the program could not be run at all
  double seconds = 0.0;
  std::string output;       ///< stdout, and stderr too with ChildStreams::merged
  std::string errors;       ///< stderr with ChildStreams::separate; why, when it did not start

  bool ok() const { return started && !timed_out && signal == 0 && exit_code == 0; }
  /// "exited with status 2", "crashed (SIGSEGV)", "ran past its 30 s limit", ...
  std::string describe() const;
};

/// Runs argv[0] (looked up on PATH) with `argv`, no shell in between, in `working_dir` when not
/// empty, killing its whole process group at `timeout_seconds`. Each stream's output beyond
/// `max_output` bytes is cut (a child that prints garbage forever must not fill the disk).
ChildResult run_child(const std::vector<std::string>& argv, double timeout_seconds,
                      const std::string& working_dir = {}, size_t max_output = 1 << 20,
                      ChildStreams streams = ChildStreams::merged);

/// The command as a person would type it (arguments with spaces quoted).
std::string command_line(const std::vector<std::string>& argv);

/// The last `lines` non-empty lines of a child's output, for an error message that stays
/// readable.
std::string tail_lines(const std::string& text, int lines);

}  // namespace pt
