// run_child with the Linux keeper: a child subreaper (prctl) that finds what the child left
// behind in /proc, and can run the child as a user of its own. Built when PT_LINUX_SANDBOX is on
// (Linux); posix_runner.cpp stands in for it elsewhere.
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <thread>

#include "grader/process/child_detail.h"
#include "grader/process/child_process.h"

namespace pt {
namespace {

using child_detail::merged_environment;
using child_detail::OutputFile;
using child_detail::start_step;

/// What the keeper tells the caller, through a pipe, once the child and all it started are gone.
struct KeeperReport {
  int status_known = 0;  ///< 1 when `status` is a wait status of the child
  int status = 0;
  int started = 0;
  int exec_errno = 0;
  int timed_out = 0;
  int disk_exceeded = 0;
  int descendants_killed = 0;
  double seconds = 0.0;
};

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The free bytes of the file system holding `path`, or -1.
double free_bytes(const std::string& path) {
  struct statvfs s;
  if (statvfs(path.c_str(), &s) != 0) return -1.0;
  return double(s.f_bavail) * double(s.f_frsize);
}

/// The processes whose parent is `parent` (from /proc: works on every kernel with /proc, unlike
/// /proc/PID/task/TID/children).
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> found;
  DIR* proc = opendir("/proc");
  if (!proc) return found;
  while (dirent* e = readdir(proc)) {
    char* end = nullptr;
    long pid = std::strtol(e->d_name, &end, 10);
    if (pid <= 0 || *end != '\0') continue;
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE* f = std::fopen(path, "r");
    if (!f) continue;
    char buf[512];
    size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    buf[n] = '\0';
    // "pid (comm) state ppid ...": comm may hold spaces and parentheses, so parse after the
    // last ')'.
    const char* close_paren = std::strrchr(buf, ')');
    if (!close_paren) continue;
    char state = 0;
    long ppid = 0;
    if (std::sscanf(close_paren + 1, " %c %ld", &state, &ppid) == 2 && ppid == parent)
      found.push_back(pid_t(pid));
  }
  closedir(proc);
  return found;
}

/// Kills every process of user `uid` at once: a helper that becomes that user sends SIGKILL to
/// every process it may signal (kill(-1)), which is exactly that user's processes.
void kill_all_of_user(long uid) {
  if (uid < 0) return;
  pid_t helper = fork();
  if (helper == 0) {
    if (setuid(uid_t(uid)) == 0) kill(-1, SIGKILL);
    _exit(0);
  }
  if (helper > 0) waitpid(helper, nullptr, 0);
}

/// In the keeper (a subreaper): kill and reap every descendant left, until there is none. Each
/// round kills the keeper's current children; the children of those then become the keeper's,
/// so the next round reaches them. Returns how many were reaped.
int end_every_descendant(long uid, int* reaped_target, pid_t target, int* target_status) {
  int reaped = 0;
  auto start = std::chrono::steady_clock::now();
  for (;;) {
    kill_all_of_user(uid);
    for (pid_t c : children_of(getpid())) {
      kill(-c, SIGKILL);
      kill(c, SIGKILL);
    }
    int st = 0;
    pid_t p;
    while ((p = waitpid(-1, &st, WNOHANG)) > 0) {
      if (p == target) {
        *reaped_target = 1;
        *target_status = st;
      } else {
        ++reaped;
      }
    }
    if (p < 0 && errno == ECHILD) break;
    if (since(start) > 30.0) break;  // a process stuck in the kernel: give up, report anyway
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return reaped;
}

/// Closes every descriptor above 2 but `keep` and `also`.
void close_all_but(std::initializer_list<int> keep, const std::vector<int>& also) {
  std::vector<int> open_fds;
  if (DIR* d = opendir("/proc/self/fd")) {
    while (dirent* e = readdir(d)) {
      char* end = nullptr;
      long fd = std::strtol(e->d_name, &end, 10);
      if (*end == '\0' && end != e->d_name && fd > 2 && fd != dirfd(d)) open_fds.push_back(int(fd));
    }
    closedir(d);
  }
  for (int fd : open_fds) {
    bool kept = false;
    for (int k : keep) kept = kept || k == fd;
    for (int k : also) kept = kept || k == fd;
    if (!kept) close(fd);
  }
}

/// Set when the keeper's parent (the caller) died: the keeper then ends the tree as at a limit.
volatile sig_atomic_t caller_gone = 0;
void on_caller_gone(int) { caller_gone = 1; }

/// The keeper: runs in a forked copy of the caller, starts the child, enforces the limits and
/// ends the whole tree, then writes its KeeperReport to `report_fd` and exits.
[[noreturn]] void keeper_main(char* const* args, char* const* envp, const ChildOptions& o,
                              int out_fd, int err_fd, int report_fd, pid_t caller) {
  KeeperReport rep;
  // The caller may run several children at once (threads): whatever descriptors of the others'
  // it held at the fork go, so that no child waits for an end of file (its nonce pipe) that
  // only another child's keeper could give.
  close_all_but({out_fd, err_fd, report_fd}, o.keep_fds);
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  // A caller that dies (killed, or a test harness stopped) must not leave the tree running.
  signal(SIGTERM, on_caller_gone);
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != caller) caller_gone = 1;  // it died before the line above
  signal(SIGCHLD, SIG_DFL);
  signal(SIGPIPE, SIG_IGN);
  int exec_pipe[2];
  if (pipe2(exec_pipe, O_CLOEXEC) != 0) {
    rep.exec_errno = errno;
    (void)!write(report_fd, &rep, sizeof rep);
    _exit(0);
  }
  const ChildLimits& lim = o.limits;
  std::vector<double> free_at_start;
  for (const std::string& d : lim.disk_watch) free_at_start.push_back(free_bytes(d));
  auto start = std::chrono::steady_clock::now();
  pid_t target = fork();
  if (target == 0) {
    close(exec_pipe[0]);
    setpgid(0, 0);
    int devnull = open("/dev/null", O_RDONLY);
    dup2(devnull, 0);
    dup2(out_fd, 1);
    dup2(err_fd, 2);
    // Every descriptor but 0-2, the exec pipe (close-on-exec) and the ones asked for goes.
    long max_fd = sysconf(_SC_OPEN_MAX);
    if (max_fd < 0 || max_fd > 65536) max_fd = 65536;
    for (int fd = 3; fd < max_fd; ++fd) {
      bool keep = fd == exec_pipe[1];
      for (int k : o.keep_fds) keep = keep || fd == k;
      if (!keep) close(fd);
    }
    for (int k : o.keep_fds) fcntl(k, F_SETFD, 0);
    int step = 0;  // which step failed, for the message
    auto fail = [&](int which) {
      int msg[2] = {which, errno};
      (void)!write(exec_pipe[1], msg, sizeof msg);
      _exit(127);
    };
    if (!o.working_dir.empty() && chdir(o.working_dir.c_str()) != 0) fail(1);
    auto limit = [&](int resource, rlim_t value) {
      struct rlimit r = {value, value};
      if (setrlimit(resource, &r) != 0) fail(2);
    };
    if (lim.cpu_seconds > 0) {
      // The soft limit sends SIGXCPU (named in the message); the hard one a second later kills.
      struct rlimit r = {rlim_t(lim.cpu_seconds + 0.999), rlim_t(lim.cpu_seconds + 1.999)};
      if (setrlimit(RLIMIT_CPU, &r) != 0) fail(2);
    }
    if (lim.address_space > 0) limit(RLIMIT_AS, rlim_t(lim.address_space));
    if (lim.file_size > 0) limit(RLIMIT_FSIZE, rlim_t(lim.file_size));
    if (lim.processes > 0) limit(RLIMIT_NPROC, rlim_t(lim.processes));
    limit(RLIMIT_CORE, 0);
    if (o.gid >= 0) {
      if (setgroups(0, nullptr) != 0) fail(3);
      if (setgid(gid_t(o.gid)) != 0) fail(3);
    }
    if (o.uid >= 0) {
      if (setuid(uid_t(o.uid)) != 0) fail(4);
      if (getuid() != uid_t(o.uid) || geteuid() != uid_t(o.uid)) fail(4);
    }
    step = 5;
    execvpe(args[0], args, envp);
    fail(step);
  }
  close(exec_pipe[1]);
  if (target < 0) {
    rep.exec_errno = errno;
    (void)!write(report_fd, &rep, sizeof rep);
    _exit(0);
  }
  int msg[2] = {0, 0};
  ssize_t got = read(exec_pipe[0], msg, sizeof msg);
  close(exec_pipe[0]);
  int target_status = 0, target_reaped = 0;
  if (got > 0) {
    // It never ran the program: say which step failed (1 chdir, 2 limits, 3 group, 4 user,
    // 5 exec) in the errno's high bits.
    rep.started = 0;
    rep.exec_errno = msg[1] | (msg[0] << 16);
  } else {
    rep.started = 1;
    int polls = 0;
    for (;;) {
      int st = 0;
      pid_t done = waitpid(target, &st, WNOHANG);
      if (done == target) {
        target_reaped = 1;
        target_status = st;
        break;
      }
      if (done < 0 && errno != EINTR) break;  // no status: reported as unknown
      double elapsed = since(start);
      if (elapsed > lim.wall_seconds || caller_gone) {
        rep.timed_out = 1;
        break;
      }
      if (lim.disk_bytes > 0 && ++polls % 4 == 0) {
        for (size_t i = 0; i < lim.disk_watch.size(); ++i) {
          double now = free_bytes(lim.disk_watch[i]);
          if (free_at_start[i] >= 0 && now >= 0 && free_at_start[i] - now > double(lim.disk_bytes))
            rep.disk_exceeded = 1;
        }
        if (rep.disk_exceeded) break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 1.0 ? 5 : 25));
    }
  }
  rep.seconds = since(start);
  // Whatever is left (the child after a limit, anything it started, even after setsid) goes.
  kill(-target, SIGKILL);
  if (!target_reaped) kill(target, SIGKILL);
  rep.descendants_killed = end_every_descendant(o.uid, &target_reaped, target, &target_status);
  rep.status_known = target_reaped;
  rep.status = target_status;
  (void)!write(report_fd, &rep, sizeof rep);
  _exit(0);
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options) {
  ChildResult result;
  const bool separate = options.streams == ChildStreams::separate;
  OutputFile out, err;
  auto not_started = [&](const std::string& why) {
    result.started = false;
    result.errors = why;
    result.output = why;
    return result;
  };
  if (argv.empty()) return not_started("no program to run");
  if (out.fd < 0 || (separate && err.fd < 0))
    return not_started("cannot create a temporary file for the child's output");
  if ((options.uid >= 0 && geteuid() != 0 && uid_t(options.uid) != geteuid()))
    return not_started(std::string("cannot run ") + argv[0] + " as user " +
                       std::to_string(options.uid) + ": only root can switch users");
  // Everything the keeper and the child need is made before the fork.
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env = merged_environment(options.environment);
  std::vector<char*> envp;
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);

  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0) return not_started("cannot create a pipe for the keeper");
  const pid_t caller = getpid();
  pid_t keeper = fork();
  if (keeper < 0) {
    close(report[0]);
    close(report[1]);
    return not_started(std::string("cannot fork: ") + std::strerror(errno));
  }
  if (keeper == 0) {
    close(report[0]);
    keeper_main(args.data(), envp.data(), options, out.fd, separate ? err.fd : out.fd, report[1],
                caller);
  }
  close(report[1]);
  KeeperReport rep;
  size_t have = 0;
  while (have < sizeof rep) {
    ssize_t n = read(report[0], reinterpret_cast<char*>(&rep) + have, sizeof rep - have);
    if (n > 0) {
      have += size_t(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;
    }
  }
  close(report[0]);
  int keeper_status = 0;
  while (waitpid(keeper, &keeper_status, 0) < 0 && errno == EINTR) {
  }
  result.output = out.head(options.limits.max_output);
  if (separate) result.errors = err.head(options.limits.max_output);
  if (have != sizeof rep) {
    // The keeper itself was killed (possible only when the child runs as our own user).
    result.unknown_status = true;
    return result;
  }
  result.seconds = rep.seconds;
  result.descendants_killed = rep.descendants_killed;
  if (!rep.started) {
    int step = rep.exec_errno >> 16, code = rep.exec_errno & 0xffff;
    std::string why = std::string(start_step(step)) + " " + argv[0] + ": " + std::strerror(code);
    result.started = false;
    result.errors = why;
    result.output = why;
    return result;
  }
  result.timed_out = rep.timed_out != 0;
  result.disk_exceeded = rep.disk_exceeded != 0;
  if (result.timed_out || result.disk_exceeded) return result;
  if (!rep.status_known) {
    result.unknown_status = true;
  } else if (WIFEXITED(rep.status)) {
    result.exit_code = WEXITSTATUS(rep.status);
  } else if (WIFSIGNALED(rep.status)) {
    result.signal = WTERMSIG(rep.status);
  } else {
    result.unknown_status = true;  // stopped, continued: nothing we can count as an ending
  }
  return result;
}

}  // namespace pt
