#include "app/viewer/crash_witness.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>

namespace pt {

namespace {

// Fixed buffers, read by the handler without a lock or an allocation (neither is safe in a
// signal handler): a torn text, if a render starts as another crashes, is a garbled note only.
thread_local char t_activity[256];
char g_render[512];
std::atomic<bool> g_render_on{false};
int g_fd = -1;

void copy(char* to, size_t size, const std::string& what) {
  const size_t n = std::min(what.size(), size - 1);
  std::memcpy(to, what.data(), n);
  to[n] = '\0';
}

void on_crash(int sig) {
  const char* what = t_activity[0] ? t_activity : g_render_on.load() ? g_render : "";
  if (g_fd >= 0 && what[0]) {
    const ssize_t written = write(g_fd, what, std::strlen(what));
    (void)written;  // nothing else to try: the process is dying
  }
  // SA_RESETHAND put the default action back; SA_NODEFER lets it act now.
  raise(sig);
}

}  // namespace

void install_crash_witness(int fd) {
  g_fd = fd;
  struct sigaction a {};
  a.sa_handler = on_crash;
  a.sa_flags = SA_RESETHAND | SA_NODEFER;
  sigemptyset(&a.sa_mask);
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) sigaction(sig, &a, nullptr);
}

void set_thread_activity(const std::string& what) { copy(t_activity, sizeof t_activity, what); }

void set_render_activity(const std::string& what) {
  g_render_on = false;
  copy(g_render, sizeof g_render, what);
  g_render_on = !what.empty();
}

}  // namespace pt
