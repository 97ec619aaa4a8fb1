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

namespace pt::grader {

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
                      const std::string& working_dir, size_t max_output) {
  ChildResult result;
  // Output goes to a temporary file rather than a pipe: nothing to drain while we wait, and a
  // child that floods its output only grows a file that we read the head of.
  char path[] = "/tmp/pt-grader-child-XXXXXX";
  int fd = mkstemp(path);
  if (fd < 0 || argv.empty()) {
    result.started = false;
    result.output = "cannot create a temporary file for the child's output";
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fd, 1);
  posix_spawn_file_actions_adddup2(&actions, fd, 2);
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
  int err = posix_spawnp(&pid, use[0], &actions, &attr, use, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (err != 0) {
    close(fd);
    std::remove(path);
    result.started = false;
    result.output = std::string("cannot run ") + argv[0] + ": " + std::strerror(err);
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
  close(fd);
  std::ifstream in(path, std::ios::binary);
  result.output.resize(max_output);
  in.read(result.output.data(), std::streamsize(max_output));
  result.output.resize(size_t(in.gcount()));
  if (std::filesystem::file_size(path) > max_output) result.output += "\n[... output cut ...]\n";
  std::remove(path);
  return result;
}

}  // namespace pt::grader
