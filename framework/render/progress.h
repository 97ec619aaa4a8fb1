// Not needed for the assignment.
// A progress bar with an ETA, for renders a person waits for at a terminal.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>

namespace pt {

/// A one-line bar "[#####.....]  45%  ETA 3.2 s" redrawn in place on `out`. Threads report
/// finished work with advance(); whichever thread gets the lock redraws, at most ten times a
/// second, and the others go on working. A disabled bar draws nothing, so a render piped into a
/// file or run by a test leaves no control characters behind.
class ProgressBar {
 public:
  ProgressBar(long total_work, bool enabled, std::FILE* out = stderr);
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Whether stderr is a terminal, the condition under which a render shows its bar.
  static bool stderr_is_terminal();

  void advance(long work);
  /// Erases the bar, so the line after it starts clean.
  void finish();

 private:
  void draw(long done);

  using Clock = std::chrono::steady_clock;
  long total_;
  bool enabled_;
  std::FILE* out_;
  std::atomic<long> done_{0};
  std::mutex draw_mutex_;
  Clock::time_point start_, last_draw_;
};

}  // namespace pt
