#include "app/viewer/terminal_log.h"

#include <unistd.h>

#include <cstdio>

namespace pt {

TerminalLog::~TerminalLog() {
  if (reader_.joinable()) {
    // Restore the terminal as fd 2: the pipe's last writer closes and the reader sees its end.
    std::fflush(stderr);
    dup2(terminal_fd_, 2);
    reader_.join();
  }
}

bool TerminalLog::start() {
  int fds[2];
  if (pipe(fds) != 0) return false;
  terminal_fd_ = dup(2);
  if (terminal_fd_ < 0 || dup2(fds[1], 2) < 0) {
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  close(fds[1]);
  read_fd_ = fds[0];
  setvbuf(stderr, nullptr, _IONBF, 0);
  reader_ = std::thread([this] { pump(); });
  return true;
}

void TerminalLog::pump() {
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(read_fd_, buffer, sizeof buffer);
    if (n <= 0) break;
    ssize_t off = 0;
    while (off < n) {
      const ssize_t w = write(terminal_fd_, buffer + off, size_t(n - off));
      if (w <= 0) break;
      off += w;
    }
    std::lock_guard lock(mutex_);
    for (ssize_t i = 0; i < n; ++i) {
      if (buffer[i] == '\n') {
        append(partial_);
        partial_.clear();
      } else if (partial_.size() < 4096) {
        partial_ += buffer[i];
      }
    }
  }
  close(read_fd_);
}

void TerminalLog::append(const std::string& line) {
  lines_.push_back(line);
  if (lines_.size() > kKeep) {
    lines_.pop_front();
    ++first_;
  }
}

void TerminalLog::add(const std::string& line) {
  std::fprintf(stderr, "%s\n", line.c_str());
  if (!reader_.joinable()) {
    std::lock_guard lock(mutex_);
    append(line);
  }
}

std::vector<std::string> TerminalLog::since(size_t from, size_t* next) const {
  std::lock_guard lock(mutex_);
  std::vector<std::string> out;
  for (size_t k = std::max(from, first_); k < first_ + lines_.size(); ++k)
    out.push_back(lines_[k - first_]);
  *next = first_ + lines_.size();
  return out;
}

}  // namespace pt
