#include "framework/process/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace pt {
namespace {

/// A temporary file for a child's output, removed when the run is over. Output goes to files
/// rather than pipes: nothing to drain while we wait, and a child that floods its output only
/// grows a file that we read the head of.
struct OutputFile {
  std::string path;
  int fd = -1;
  OutputFile() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "pt-child-XXXXXX").string();
    fd = mkstemp(tmpl.data());
    if (fd >= 0) path = tmpl;
  }
  ~OutputFile() {
    if (fd >= 0) close(fd);
    if (!path.empty()) std::remove(path.c_str());
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Its first `max_output` bytes, with a mark where the rest was cut.
  std::string head(size_t max_output) const {
    std::ifstream in(path, std::ios::binary);
    std::string text(max_output, '\0');
    in.read(text.data(), std::streamsize(max_output));
    text.resize(size_t(in.gcount()));
    std::error_code ec;
    if (std::filesystem::file_size(path, ec) > max_output) text += "\n[... output cut ...]\n";
    return text;
  }
};

}  // namespace

std::string ChildResult::describe() const {
  if (!started) return "could not be started";
  char buf[120];
  if (timed_out) {
    std::snprintf(buf, sizeof buf, "ran past its time limit (%.0f s) and was stopped", seconds);
  } else if (signal != 0) {
    const char* name = signal == SIGSEGV   ? "SIGSEGV, a bad memory access"
                       : signal == SIGABRT ? "SIGABRT, an assertion or an uncaught exception"
                       : signal == SIGFPE  ? "SIGFPE, an arithmetic error"
                       : signal == SIGBUS  ? "SIGBUS, a bad memory access"
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
  ChildResult result;
  const bool separate = streams == ChildStreams::separate;
  OutputFile out, err;
  if (out.fd < 0 || (separate && err.fd < 0) || argv.empty()) {
    result.started = false;
    result.errors = argv.empty() ? "no program to run"
                                 : "cannot create a temporary file for the child's output";
    result.output = result.errors;
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out.fd, 1);
  posix_spawn_file_actions_adddup2(&actions, separate ? err.fd : out.fd, 2);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  // Its own process group, so a time-out also stops what it started (ctest's tests, a shell's
  // children).
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);

  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  // posix_spawn has no working directory action in glibc 2.36's portable API: run through
  // `env -C DIR` when one is asked for.
  std::vector<std::string> wrapped;
  std::vector<char*> wargs;
  char** use = args.data();
  if (!working_dir.empty()) {
    wrapped = {"env", "-C", working_dir};
    wrapped.insert(wrapped.end(), argv.begin(), argv.end());
    for (const std::string& a : wrapped) wargs.push_back(const_cast<char*>(a.c_str()));
    wargs.push_back(nullptr);
    use = wargs.data();
  }

  auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  int spawn_error = posix_spawnp(&pid, use[0], &actions, &attr, use, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (spawn_error != 0) {
    result.started = false;
    result.errors = std::string("cannot run ") + argv[0] + ": " + std::strerror(spawn_error);
    result.output = result.errors;
    return result;
  }
  int status = 0;
  for (;;) {
    pid_t done = waitpid(pid, &status, WNOHANG);
    double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == pid) break;
    if (done < 0) {
      status = 0;
      break;
    }
    if (elapsed > timeout_seconds) {
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      result.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 1.0 ? 5 : 50));
  }
  // Whatever the child left running in its group (a test's own children) goes with it.
  kill(-pid, SIGKILL);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.timed_out) {
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  }
  result.output = out.head(max_output);
  if (separate) result.errors = err.head(max_output);
  return result;
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
