// Not needed for the assignment: the definitions of framework/render/progress.h.
#include "framework/render/progress.h"

#include <algorithm>
#include <string>

#include <unistd.h>

namespace pt {

ProgressBar::ProgressBar(long total_work, bool enabled, std::FILE* out)
    : total_(std::max(total_work, 1L)), enabled_(enabled), out_(out),
      start_(Clock::now()), last_draw_(start_ - std::chrono::seconds(1)) {}

bool ProgressBar::stderr_is_terminal() { return isatty(fileno(stderr)) != 0; }

void ProgressBar::advance(long work) {
  long done = done_.fetch_add(work) + work;
  if (!enabled_) return;
  std::unique_lock<std::mutex> lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  auto now = Clock::now();
  if (done < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(done);
}

void ProgressBar::draw(long done) {
  const int width = 30;
  double fraction = std::min(1.0, double(done) / double(total_));
  int filled = int(fraction * width);
  double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  std::string bar(size_t(filled), '#');
  bar.append(size_t(width - filled), '.');
  if (done > 0 && done < total_) {
    double eta = elapsed * (1.0 - fraction) / fraction;
    std::fprintf(out_, "\r[%s] %3d%%  ETA %.1f s   ", bar.c_str(), int(fraction * 100), eta);
  } else {
    std::fprintf(out_, "\r[%s] %3d%%  %.1f s       ", bar.c_str(), int(fraction * 100), elapsed);
  }
  std::fflush(out_);
}

void ProgressBar::finish() {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(draw_mutex_);
  std::fprintf(out_, "\r%60s\r", "");
  std::fflush(out_);
}

}  // namespace pt
