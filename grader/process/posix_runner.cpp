// run_child without the Linux keeper, for every system the keeper does not build on (macOS, and
// a Linux build with PT_LINUX_SANDBOX off): plain POSIX. The child is a process group of its own,
// watched by the caller; at its end or at a limit the whole group is killed. What the child moves
// out of its group (setsid, setpgid) is not followed, and it cannot be run as another user: a
// student's own grader needs neither, the Gradescope grader (on Linux) has both.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "grader/process/child_detail.h"
#include "grader/process/child_process.h"

namespace pt {
namespace {

using child_detail::merged_environment;
using child_detail::OutputFile;
using child_detail::start_step;

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The free bytes of the file system holding `path`, or -1.
double free_bytes(const std::string& path) {
  struct statvfs s;
  if (statvfs(path.c_str(), &s) != 0) return -1.0;
  return double(s.f_bavail) * double(s.f_frsize);
}

/// In the forked child: set it up as `o` says and run the program; on failure, write which step
/// failed and errno to `report_fd` and exit 127.
[[noreturn]] void start_in_child(char* const* args, char** envp, const ChildOptions& o, int out_fd,
                                 int err_fd, int report_fd) {
  setpgid(0, 0);
  int devnull = open("/dev/null", O_RDONLY);
  dup2(devnull, 0);
  dup2(out_fd, 1);
  dup2(err_fd, 2);
  long max_fd = sysconf(_SC_OPEN_MAX);
  if (max_fd < 0 || max_fd > 65536) max_fd = 65536;
  for (int fd = 3; fd < max_fd; ++fd) {
    bool keep = fd == report_fd;
    for (int k : o.keep_fds) keep = keep || fd == k;
    if (!keep) close(fd);
  }
  for (int k : o.keep_fds) fcntl(k, F_SETFD, 0);
  auto fail = [&](int step) {
    int msg[2] = {step, errno};
    (void)!write(report_fd, msg, sizeof msg);
    _exit(127);
  };
  if (!o.working_dir.empty() && chdir(o.working_dir.c_str()) != 0) fail(1);
  const ChildLimits& lim = o.limits;
  auto limit = [&](int resource, rlim_t soft, rlim_t hard) {
    struct rlimit r = {soft, hard};
    if (setrlimit(resource, &r) != 0) fail(2);
  };
  if (lim.cpu_seconds > 0)
    limit(RLIMIT_CPU, rlim_t(lim.cpu_seconds + 0.999), rlim_t(lim.cpu_seconds + 1.999));
  if (lim.address_space > 0) limit(RLIMIT_AS, rlim_t(lim.address_space), rlim_t(lim.address_space));
  if (lim.file_size > 0) limit(RLIMIT_FSIZE, rlim_t(lim.file_size), rlim_t(lim.file_size));
  if (lim.processes > 0) limit(RLIMIT_NPROC, rlim_t(lim.processes), rlim_t(lim.processes));
  limit(RLIMIT_CORE, 0, 0);
  // execvp looks the program up on PATH and runs it with `environ`: this process's own copy.
  environ = envp;
  execvp(args[0], args);
  fail(5);
  _exit(127);  // not reached: fail exits
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
  const ChildConfinement& c = options.confinement;
  if (options.uid >= 0 || options.gid >= 0 || c.namespaces || c.refuse_ipc_and_network)
    return not_started(std::string("cannot run ") + argv[0] +
                       " as another user or confined: this build has no sandbox "
                       "(PT_LINUX_SANDBOX is off)");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env = merged_environment(options.environment);
  std::vector<char*> envp;
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);

  // A pipe that closes (close-on-exec) when the program starts, or carries why it did not.
  int report[2];
  if (pipe(report) != 0) return not_started("cannot create a pipe to start the child");
  fcntl(report[0], F_SETFD, FD_CLOEXEC);
  fcntl(report[1], F_SETFD, FD_CLOEXEC);
  const ChildLimits& lim = options.limits;
  std::vector<double> free_at_start;
  for (const std::string& d : lim.disk_watch) free_at_start.push_back(free_bytes(d));
  auto start = std::chrono::steady_clock::now();
  pid_t child = fork();
  if (child < 0) {
    close(report[0]);
    close(report[1]);
    return not_started(std::string("cannot fork: ") + std::strerror(errno));
  }
  if (child == 0) {
    close(report[0]);
    start_in_child(args.data(), envp.data(), options, out.fd, separate ? err.fd : out.fd,
                   report[1]);
  }
  // Both sides set the group, so it is the child's before anything is signalled.
  setpgid(child, child);
  close(report[1]);
  int msg[2] = {0, 0};
  ssize_t got;
  while ((got = read(report[0], msg, sizeof msg)) < 0 && errno == EINTR) {
  }
  close(report[0]);

  int status = 0;
  bool reaped = false;
  if (got > 0) {
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    std::string why = std::string(start_step(msg[0])) + " " + argv[0] + ": " + std::strerror(msg[1]);
    return not_started(why);
  }
  int polls = 0;
  for (;;) {
    pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) {
      reaped = true;
      break;
    }
    if (done < 0 && errno != EINTR) break;  // no status: reported as unknown
    double elapsed = since(start);
    if (elapsed > lim.wall_seconds) {
      result.timed_out = true;
      break;
    }
    if (lim.disk_bytes > 0 && ++polls % 4 == 0) {
      for (size_t i = 0; i < lim.disk_watch.size(); ++i) {
        double now = free_bytes(lim.disk_watch[i]);
        if (free_at_start[i] >= 0 && now >= 0 && free_at_start[i] - now > double(lim.disk_bytes))
          result.disk_exceeded = true;
      }
      if (result.disk_exceeded) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 1.0 ? 5 : 25));
  }
  result.seconds = since(start);
  // Whatever is left of its group goes with it.
  kill(-child, SIGKILL);
  if (!reaped) {
    kill(child, SIGKILL);
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
  }
  result.output = out.head(lim.max_output);
  if (separate) result.errors = err.head(lim.max_output);
  if (result.timed_out || result.disk_exceeded) return result;
  if (!reaped) {
    result.unknown_status = true;
  } else if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  } else {
    result.unknown_status = true;
  }
  return result;
}

}  // namespace pt
