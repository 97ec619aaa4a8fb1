#include "grader/sandbox.h"

#include <fcntl.h>
#include <grp.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "grader/student_traces.h"

namespace fs = std::filesystem;

namespace pt::grader {

/// The slot's lock and its uids in use (by scratch folder), and what could not be removed.
struct SandboxState {
  int lock_fd = -1;
  std::mutex mutex;
  std::map<std::string, long> uid_of_scratch;
  long next = 0;
  std::string leftovers;
  ~SandboxState() {
    if (lock_fd >= 0) close(lock_fd);
  }
};

namespace {

// The locks of the slots: a folder of root's alone, so no student's process can take or hold one.
const char* const kSlotLocks = "/run/pt-grader";
constexpr long kMqueueMagic = 0x19800202;

/// Takes the first free slot from `first` on (wrapping), with an exclusive lock on its file that
/// lasts as long as `state` (a grader that dies frees its slot). Throws when none is free.
int take_slot(int first, SandboxState& state) {
  mkdir("/run", 0755);
  mkdir(kSlotLocks, 0700);
  struct stat st;
  if (lstat(kSlotLocks, &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != 0)
    throw std::runtime_error(std::string(kSlotLocks) + " is not a folder of root's: no slot can be taken");
  chmod(kSlotLocks, 0700);
  for (long i = 0; i < kSlots; ++i) {
    int slot = int((first + i) % kSlots);
    std::string path = std::string(kSlotLocks) + "/slot-" + std::to_string(slot) + ".lock";
    int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0) continue;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) {
      state.lock_fd = fd;
      return slot;
    }
    close(fd);
  }
  throw std::runtime_error("every one of the " + std::to_string(kSlots) +
                           " grading slots is taken (" + kSlotLocks + ")");
}

/// Where namespaces are refused: every shared writable place gets a deny ACL for the students'
/// group (or, on a file system without ACLs, loses its world write bit); then a process of that
/// group checks it can write none. A message queue folder needs neither: RLIMIT_MSGQUEUE 0 keeps
/// a student's process from making a queue there.
void keep_shared_places_from_students(long some_uid) {
  const WritablePlaces& places = world_writable_places();
  std::vector<std::string> all = places.folders;
  all.insert(all.end(), places.files.begin(), places.files.end());
  std::vector<std::string> checked;
  for (const std::string& p : all) {
    struct statfs fsinfo;
    if (statfs(p.c_str(), &fsinfo) == 0 && long(fsinfo.f_type) == kMqueueMagic) continue;
    if (!deny_group_write(p, kStudentGroup).empty()) {
      struct stat st;
      if (lstat(p.c_str(), &st) != 0 || chmod(p.c_str(), st.st_mode & ~mode_t(S_IWOTH)) != 0)
        throw std::runtime_error("cannot keep the student's user from writing " + p);
    }
    checked.push_back(p);
  }
  const std::string writable = as_student_user(some_uid, [&] {
    std::string found;
    for (const std::string& p : checked)
      if (access(p.c_str(), W_OK) == 0) found += p + "\n";
    return found;
  });
  if (!writable.empty())
    throw std::runtime_error("the student's user could still write:\n" + writable);
}

}  // namespace

std::string as_student_user(long uid, const std::function<std::string()>& work) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("cannot make a pipe");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot fork");
  if (child == 0) {
    close(fds[0]);
    const gid_t group = gid_t(kStudentGroup);
    if (setgroups(1, &group) != 0 || setgid(gid_t(uid)) != 0 || setuid(uid_t(uid)) != 0 ||
        getuid() != uid_t(uid))
      _exit(2);
    const std::string out = work();
    for (size_t at = 0; at < out.size();) {
      const ssize_t w = write(fds[1], out.data() + at, out.size() - at);
      if (w <= 0) _exit(3);
      at += size_t(w);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string got;
  char buf[65536];
  for (ssize_t r; (r = read(fds[0], buf, sizeof buf)) > 0;) got.append(buf, size_t(r));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("a process as user " + std::to_string(uid) + " failed (status " +
                             std::to_string(status) + ")");
  return got;
}

bool kernel_gives_namespaces() {
  static const bool gives = [] {
    if (geteuid() != 0) return false;
    pid_t child = fork();
    if (child == 0) {
      bool ok = unshare(CLONE_NEWNS | CLONE_NEWIPC | CLONE_NEWNET) == 0 &&
                mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0;
      _exit(ok ? 0 : 1);
    }
    int status = 0;
    return child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0;
  }();
  return gives;
}

Sandbox Sandbox::standard(const std::string& scratch_root, int slot) {
  Sandbox s;
  s.state = std::make_shared<SandboxState>();
  if (geteuid() == 0) {
    int taken = take_slot(slot < 0 ? 0 : slot, *s.state);
    s.uid = kFirstStudentUid + taken * kUidsPerSlot;
    s.gid = s.uid;
    const char* wanted = std::getenv("PT_SANDBOX_NAMESPACES");
    s.namespaces = kernel_gives_namespaces() && !(wanted && std::string(wanted) == "off");
    if (!s.namespaces) keep_shared_places_from_students(s.uid);
  }
  s.scratch_root = scratch_root;
  fs::create_directories(scratch_root);
  fs::permissions(scratch_root, fs::perms(0711));
  s.limits.address_space = size_t(4) << 30;
  s.limits.processes = 256;  // threads count too (oneTBB's workers)
  s.limits.file_size = size_t(256) << 20;
  s.limits.max_output = 1 << 20;
  s.limits.disk_bytes = size_t(1) << 30;
  s.limits.disk_watch = {scratch_root, fs::temp_directory_path().string()};
  if (fs::exists("/dev/shm")) s.limits.disk_watch.push_back("/dev/shm");
  return s;
}

Sandbox Sandbox::lane(int) const {
  Sandbox s = *this;
  s.jobs = 1;
  return s;
}

std::string Sandbox::make_scratch(const std::string& name) const {
  static std::atomic<int> counter{0};
  fs::path dir = fs::path(scratch_root) /
                 (name + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  long mine = uid;
  if (protects()) {
    std::lock_guard<std::mutex> lock(state->mutex);
    mine = -1;
    for (long i = 0; i < kUidsPerSlot && mine < 0; ++i) {
      long candidate = uid + (state->next++ % kUidsPerSlot);
      bool used = false;
      for (const auto& [folder, u] : state->uid_of_scratch) used = used || u == candidate;
      if (!used) mine = candidate;
    }
    if (mine < 0)
      throw std::runtime_error("all " + std::to_string(kUidsPerSlot) + " uids of the slot are in use");
    state->uid_of_scratch[dir.string()] = mine;
  }
  if (protects() && chown(dir.c_str(), uid_t(mine), gid_t(mine)) != 0)
    throw std::runtime_error("cannot give the scratch folder " + dir.string() + " to user " +
                             std::to_string(mine));
  fs::permissions(dir, fs::perms(0700));
  return dir.string();
}

long Sandbox::uid_of(const std::string& scratch) const {
  if (!protects()) return uid;
  std::lock_guard<std::mutex> lock(state->mutex);
  auto it = state->uid_of_scratch.find(scratch);
  if (it == state->uid_of_scratch.end())
    throw std::runtime_error(scratch + " is no scratch folder of this sandbox");
  return it->second;
}

void Sandbox::finish(const std::string& scratch) const {
  std::error_code ec;
  if (!scratch.empty()) fs::remove_all(scratch, ec);
  if (!protects()) return;  // our own user's files there are not ours to judge
  long mine = -1;
  {
    std::lock_guard<std::mutex> lock(state->mutex);
    auto it = state->uid_of_scratch.find(scratch);
    if (it == state->uid_of_scratch.end()) return;
    mine = it->second;
  }
  std::string left = remove_traces_of(mine, world_writable_places().folders);
  std::error_code still;
  if (fs::exists(scratch, still)) left += "its scratch folder " + scratch + " stays; ";
  std::lock_guard<std::mutex> lock(state->mutex);
  if (!left.empty()) {
    state->leftovers += left + "\n";
  } else {
    state->uid_of_scratch.erase(scratch);  // a uid that left something is never used again
  }
}

std::string Sandbox::leftovers() const {
  if (!state) return "";
  std::lock_guard<std::mutex> lock(state->mutex);
  return state->leftovers;
}

ChildOptions Sandbox::options(const std::string& scratch, double wall_seconds) const {
  ChildOptions o;
  if (max_check_seconds > 0 && wall_seconds > max_check_seconds) wall_seconds = max_check_seconds;
  o.limits = limits;
  o.limits.wall_seconds = wall_seconds;
  o.limits.cpu_seconds = wall_seconds * 4 + 10;  // a few cores' worth: the wall limit decides
  o.uid = uid_of(scratch);
  o.gid = o.uid;
  o.working_dir = scratch;
  o.environment = {"HOME=" + scratch, "TMPDIR=" + scratch};
  if (protects()) {
    ChildConfinement& c = o.confinement;
    c.group = kStudentGroup;
    c.writable = {scratch};
    if (namespaces) {
      c.namespaces = true;
      const WritablePlaces& places = world_writable_places();
      c.cover = places.folders;
      c.cover.insert(c.cover.end(), places.files.begin(), places.files.end());
    } else {
      c.refuse_ipc_and_network = true;
    }
  }
  return o;
}

std::vector<std::string> list_gtest_tests(const std::string& executable, double wall_seconds) {
  ChildResult r = run_child({executable, "--gtest_list_tests"}, wall_seconds, {}, 16 << 20,
                            ChildStreams::separate);
  if (!r.ok())
    throw std::runtime_error("cannot list the tests of " + executable + ": it " + r.describe());
  std::vector<std::string> names;
  std::string suite;
  std::istringstream in(r.output);
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    std::string word = line.substr(line.find_first_not_of(' '));
    word = word.substr(0, word.find_first_of(" #"));
    if (line[0] != ' ') {
      suite = word;  // "Suite." (a typed or parametrized suite keeps its prefix)
    } else {
      names.push_back(suite + word);
    }
  }
  return names;
}

std::string check_scratch_output(const std::string& path, const Sandbox& sandbox) {
  struct stat st;
  if (lstat(path.c_str(), &st) != 0) return "it wrote no file " + path;
  if (S_ISLNK(st.st_mode)) return path + " is a symbolic link, not a render";
  if (!S_ISREG(st.st_mode)) return path + " is not a regular file";
  if (st.st_nlink != 1) return path + " is a hard link to another file, not a render";
  struct stat folder;
  if (sandbox.protects() &&
      (lstat(fs::path(path).parent_path().c_str(), &folder) != 0 || st.st_uid != folder.st_uid))
    return path + " was not written by the render";
  return "";
}

}  // namespace pt::grader
