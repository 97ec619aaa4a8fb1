// What the viewer's process writes to its terminal, kept also for the page: the stubs' "not
// implemented" lines and every warning reach the student where they are looking.
#pragma once

#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace pt {

/// Tees standard error: fd 2 becomes a pipe whose reader thread copies every byte to the
/// terminal's standard error and keeps the last lines. Lines are numbered so the page asks only
/// for those it has not seen.
class TerminalLog {
 public:
  TerminalLog() = default;
  ~TerminalLog();
  /// Starts the tee. False (and the log stays empty) when the pipe cannot be made.
  bool start();
  /// Adds a line of the viewer's own (it is also written to the terminal).
  void add(const std::string& line);
  /// Lines numbered `from` on (the first line is 0), and in *next the number after the last.
  std::vector<std::string> since(size_t from, size_t* next) const;

 private:
  void append(const std::string& line);
  void pump();

  static constexpr size_t kKeep = 500;
  mutable std::mutex mutex_;
  std::deque<std::string> lines_;
  size_t first_ = 0;  ///< number of lines_.front()
  std::string partial_;
  int read_fd_ = -1, terminal_fd_ = -1;
  std::thread reader_;
};

}  // namespace pt
