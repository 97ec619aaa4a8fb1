// Runs a helper program (the pathtracer, node) with an argument vector, no shell in between.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pt::web {

/// What a finished child process left behind: its exit code and what it printed.
struct ProcessResult {
  int exit_code = -1;    ///< -1 when it could not be started or was killed by a signal
  std::string out;       ///< its standard output
  std::string err;       ///< its standard error, or why it could not be started
};

/// Runs argv[0] (searched in PATH when it has no slash) with argv, waits for it, and returns
/// what it printed. Arguments are passed as they are, so flags with spaces need no quoting.
ProcessResult run_process(const std::vector<std::string>& argv);

/// The last `lines` lines of a program's output, for an error message that stays readable.
std::string tail_lines(const std::string& text, int lines);

}  // namespace pt::web
