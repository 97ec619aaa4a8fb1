#include "grader/process/child_process.h"

#include <signal.h>

#include <cstdio>
#include <cstring>
#include <sstream>

namespace pt {

std::string ChildResult::describe() const {
  if (!started) return "could not be started";
  if (unknown_status) return "ended in a way that gave no exit status (counted as a failure)";
  char buf[160];
  if (timed_out) {
    std::snprintf(buf, sizeof buf, "ran past its time limit (%.0f s) and was stopped", seconds);
  } else if (disk_exceeded) {
    std::snprintf(buf, sizeof buf, "wrote more to disk than it is allowed and was stopped");
  } else if (signal != 0) {
    const char* name = signal == SIGSEGV   ? "SIGSEGV, a bad memory access"
                       : signal == SIGABRT ? "SIGABRT, an assertion, an uncaught exception or "
                                             "memory it could not allocate"
                       : signal == SIGFPE  ? "SIGFPE, an arithmetic error"
                       : signal == SIGBUS  ? "SIGBUS, a bad memory access"
                       : signal == SIGXCPU ? "SIGXCPU, it used up its CPU time limit"
                       : signal == SIGXFSZ ? "SIGXFSZ, it wrote a file past the size limit"
                       : signal == SIGKILL ? "SIGKILL, killed (its CPU time or a memory limit)"
                                           : strsignal(signal);
    std::snprintf(buf, sizeof buf, "crashed (%s)", name);
  } else {
    std::snprintf(buf, sizeof buf, "exited with status %d", exit_code);
  }
  return buf;
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) {
    if (!s.empty()) s += ' ';
    s += a.find_first_of(" \t\"'") == std::string::npos ? a : "'" + a + "'";
  }
  return s;
}

ChildResult run_child(const std::vector<std::string>& argv, double timeout_seconds,
                      const std::string& working_dir, size_t max_output, ChildStreams streams) {
  ChildOptions o;
  o.limits.wall_seconds = timeout_seconds;
  o.limits.max_output = max_output;
  o.working_dir = working_dir;
  o.streams = streams;
  return run_child(argv, o);
}

std::string tail_lines(const std::string& text, int lines) {
  std::vector<std::string> all;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) all.push_back(line);
  }
  std::string joined;
  size_t first = all.size() > static_cast<size_t>(lines) ? all.size() - lines : 0;
  for (size_t i = first; i < all.size(); ++i) joined += (i > first ? "\n" : "") + all[i];
  return joined;
}

}  // namespace pt
