// run_child with the Linux keeper: a child subreaper (prctl) that finds what the child left
// behind in /proc, and can run the child as a user of its own. Built when PT_LINUX_SANDBOX is on
// (Linux); posix_runner.cpp stands in for it elsewhere.
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <signal.h>
#include <stddef.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
  int killed_from_outside = 0;
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

/// Whether `inner` is `outer` or lies below it.
bool within(const std::string& inner, const std::string& outer) {
  return inner.compare(0, outer.size(), outer) == 0 &&
         (inner.size() == outer.size() || inner[outer.size()] == '/' || outer == "/");
}

/// In the child, as root, before it becomes its user: new mount, IPC and network namespaces, and
/// every shared writable folder made its own and empty (a tmpfs), or read-only where it holds a
/// folder that must stay writable (a test's scratch under /tmp). Returns false with errno set.
bool enter_namespaces(const ChildConfinement& c) {
  if (unshare(CLONE_NEWNS | CLONE_NEWIPC | CLONE_NEWNET) != 0) return false;
  // Nothing mounted below reaches the caller's namespace.
  if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return false;
  std::vector<std::string> cover = c.cover, emptied;
  std::sort(cover.begin(), cover.end());  // a folder before what lies in it
  for (const std::string& w : cover) {
    bool gone = false;
    for (const std::string& e : emptied) gone = gone || within(w, e);
    if (gone) continue;
    struct stat st;
    if (lstat(w.c_str(), &st) != 0) continue;  // gone since it was found
    const unsigned long ro = MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV;
    if (!S_ISDIR(st.st_mode)) {
      if (mount(w.c_str(), w.c_str(), nullptr, MS_BIND, nullptr) != 0) return false;
      if (mount(nullptr, w.c_str(), nullptr, ro, nullptr) != 0) return false;
      continue;
    }
    std::vector<std::string> inside;
    for (const std::string& k : c.writable)
      if (within(k, w) && k != w) inside.push_back(k);
    if (inside.empty()) {
      char options[64];
      std::snprintf(options, sizeof options, "size=16m,mode=%o", unsigned(st.st_mode & 07777));
      if (mount("pt-empty", w.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options) != 0) return false;
      emptied.push_back(w);
      continue;
    }
    // Each writable folder a mount of its own (which stays writable), then the folder around
    // them read-only: its own mount only, not theirs.
    for (const std::string& k : inside)
      if (mount(k.c_str(), k.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
    if (mount(w.c_str(), w.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
    if (mount(nullptr, w.c_str(), nullptr, ro, nullptr) != 0) return false;
  }
  return true;
}

/// In the child, as its user, just before exec: a seccomp filter that refuses the system calls
/// that make something outside the file system another process could open (SysV shared memory,
/// semaphores and message queues, POSIX message queues, sockets of every family), and every
/// system call of another ABI (i386's ipc and socketcall, x32). Returns false with errno set.
bool refuse_ipc_and_network() {
#if defined(__x86_64__)
  const unsigned arch = AUDIT_ARCH_X86_64;
#elif defined(__aarch64__)
  const unsigned arch = AUDIT_ARCH_AARCH64;
#else
  errno = ENOSYS;  // no filter for this machine: refuse to run rather than run unconfined
  return false;
#endif
  const unsigned refused[] = {SYS_shmget, SYS_semget, SYS_msgget, SYS_mq_open, SYS_socket};
  const unsigned n = sizeof refused / sizeof refused[0];
  const unsigned deny = SECCOMP_RET_ERRNO | (EACCES & SECCOMP_RET_DATA);
  std::vector<sock_filter> f;
  f.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)));
  f.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, arch, 1, 0));
  f.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS));
  f.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)));
#if defined(__x86_64__)
  f.push_back(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000u, 0, 1));  // x32's numbers
  f.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS));
#endif
  for (unsigned i = 0; i < n; ++i) {
    f.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, refused[i], 0, 1));
    f.push_back(BPF_STMT(BPF_RET | BPF_K, deny));
  }
  f.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
  sock_fprog prog = {static_cast<unsigned short>(f.size()), f.data()};
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
  return syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &prog) == 0;
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
    const ChildConfinement& c = o.confinement;
    if (c.refuse_ipc_and_network) limit(RLIMIT_MSGQUEUE, 0);
    if (c.namespaces && !enter_namespaces(c)) fail(6);
    if (o.gid >= 0) {
      gid_t group = gid_t(c.group);
      if (setgroups(c.group >= 0 ? 1 : 0, &group) != 0) fail(3);
      if (setgid(gid_t(o.gid)) != 0) fail(3);
    }
    if (o.uid >= 0) {
      if (setuid(uid_t(o.uid)) != 0) fail(4);
      if (getuid() != uid_t(o.uid) || geteuid() != uid_t(o.uid)) fail(4);
    }
    if (c.refuse_ipc_and_network && !refuse_ipc_and_network()) fail(7);
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
    // It never ran the program: say which step failed (child_detail's start_step) in the
    // errno's high bits.
    rep.started = 0;
    rep.exec_errno = msg[1] | (msg[0] << 16);
  } else {
    rep.started = 1;
    int polls = 0;
    for (;;) {
      int st = 0;
      struct rusage used;
      pid_t done = wait4(target, &st, WNOHANG, &used);
      if (done == target) {
        target_reaped = 1;
        target_status = st;
        // SIGKILL that none of the keeper's limits sent: only the CPU limit's hard end sends
        // it by itself, so under that CPU time it came from elsewhere (another grader, the
        // machine's OOM killer, an operator, or the program itself).
        double cpu = double(used.ru_utime.tv_sec + used.ru_stime.tv_sec) +
                     1e-6 * double(used.ru_utime.tv_usec + used.ru_stime.tv_usec);
        rep.killed_from_outside = WIFSIGNALED(st) && WTERMSIG(st) == SIGKILL &&
                                  (lim.cpu_seconds <= 0 || cpu < lim.cpu_seconds + 0.5);
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
  result.killed_from_outside = rep.killed_from_outside != 0;
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
