#include "grader/sandbox.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <thread>
#include <filesystem>
#include <random>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace pt::grader {
Sandbox Sandbox::standard(const std::string& scratch_root, int slot) {
  Sandbox s;
  if (geteuid() == 0) {
    s.uid = 60000 + slot;
    s.gid = 60000 + slot;
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

Sandbox Sandbox::lane(int k) const {
  Sandbox s = *this;
  if (protects()) {
    s.uid = uid + k;
    s.gid = gid + k;
  }
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
  if (protects() && chown(dir.c_str(), uid_t(uid), gid_t(gid)) != 0)
    throw std::runtime_error("cannot give the scratch folder " + dir.string() + " to user " +
                             std::to_string(uid));
  fs::permissions(dir, fs::perms(0700));
  return dir.string();
}

void Sandbox::finish(const std::string& scratch) const {
  std::error_code ec;
  if (!scratch.empty()) fs::remove_all(scratch, ec);
  if (!protects()) return;  // our own user's files there are not ours to judge
  for (const char* shared : {"/tmp", "/var/tmp", "/dev/shm"}) {
    for (fs::directory_iterator it(shared, ec), end; !ec && it != end; it.increment(ec)) {
      struct stat st;
      if (lstat(it->path().c_str(), &st) == 0 && st.st_uid == uid_t(uid))
        fs::remove_all(it->path(), ec);
    }
  }
}

ChildOptions Sandbox::options(const std::string& scratch, double wall_seconds) const {
  ChildOptions o;
  if (max_check_seconds > 0 && wall_seconds > max_check_seconds) wall_seconds = max_check_seconds;
  o.limits = limits;
  o.limits.wall_seconds = wall_seconds;
  o.limits.cpu_seconds = wall_seconds * 4 + 10;  // a few cores' worth: the wall limit decides
  o.uid = uid;
  o.gid = gid;
  o.working_dir = scratch;
  o.environment = {"HOME=" + scratch, "TMPDIR=" + scratch};
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
  if (sandbox.protects() && st.st_uid != uid_t(sandbox.uid))
    return path + " was not written by the render";
  return "";
}

}  // namespace pt::grader
