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
namespace {

/// A file the grader opened for the child to append its report to; unlinked at once, so only
/// the descriptor reaches it.
struct ReportFile {
  int fd = -1;
  ReportFile() {
    std::string tmpl = (fs::temp_directory_path() / "pt-report-XXXXXX").string();
    fd = mkstemp(tmpl.data());
    if (fd >= 0) unlink(tmpl.c_str());
  }
  ~ReportFile() {
    if (fd >= 0) close(fd);
  }
  std::string contents(size_t limit) const {
    std::string text;
    char buf[4096];
    off_t at = 0;
    for (ssize_t n; text.size() < limit && (n = pread(fd, buf, sizeof buf, at)) > 0; at += n)
      text.append(buf, size_t(n));
    return text;
  }
};

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

}  // namespace

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

std::string draw_nonce() {
  std::random_device device;  // the system's entropy (getrandom), not a seeded generator
  char buf[40];
  std::snprintf(buf, sizeof buf, "%08x%08x%08x%08x", device(), device(), device(), device());
  return buf;
}

SealedStatus judge_sealed_report(const std::string& report, const std::string& nonce,
                                 const std::string& name, const ChildResult& run,
                                 std::string* why) {
  int lines_for_test = 0, ends = 0, forged = 0;
  std::string status;
  std::istringstream in(report);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> w = split_words(line);
    if (w.size() < 3 || w[0] != "PTREPORT" || w[1] != nonce) {
      ++forged;
      continue;
    }
    if (w[2] == "test" && w.size() == 5) {
      if (w[3] == name) {
        ++lines_for_test;
        status = w[4];
      } else {
        ++forged;  // a test we did not ask for
      }
    } else if (w[2] == "end" && w.size() == 4 && w[3] == "1") {
      ++ends;
    } else {
      ++forged;
    }
  }
  auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return SealedStatus::failed;
  };
  if (forged > 0) return fail("its report holds lines the test harness did not write");
  if (!run.ok()) return fail("the test " + run.describe());
  if (lines_for_test == 0 || ends != 1)
    return fail("the test ended before it finished (exit() or _Exit() inside a test?)");
  if (lines_for_test > 1) return fail("the test reported more than once");
  if (status == "passed") return SealedStatus::passed;
  if (status == "skipped") return SealedStatus::skipped;
  return fail("failed");
}

SealedTest run_sealed_test(const std::string& executable, const std::string& name,
                           const Sandbox& sandbox, double wall_seconds,
                           const std::vector<std::string>& environment) {
  SealedTest t;
  t.name = name;
  ReportFile report;
  int nonce_pipe[2] = {-1, -1};
  if (report.fd < 0 || pipe(nonce_pipe) != 0) {
    t.why = "the grader cannot make the test's report descriptors";
    return t;
  }
  std::string nonce = draw_nonce() + draw_nonce();
  std::string line = nonce + "\n";
  bool written = write(nonce_pipe[1], line.data(), line.size()) == ssize_t(line.size());
  close(nonce_pipe[1]);
  if (!written) {
    close(nonce_pipe[0]);
    t.why = "the grader cannot pass the test its nonce";
    return t;
  }
  std::string scratch;
  try {
    scratch = sandbox.make_scratch("test");
  } catch (const std::exception& e) {
    close(nonce_pipe[0]);
    t.why = e.what();
    return t;
  }
  ChildOptions o = sandbox.options(scratch, wall_seconds);
  o.keep_fds = {report.fd, nonce_pipe[0]};
  o.environment.push_back("PT_REPORT_FD=" + std::to_string(report.fd));
  o.environment.push_back("PT_NONCE_FD=" + std::to_string(nonce_pipe[0]));
  o.environment.insert(o.environment.end(), environment.begin(), environment.end());
  ChildResult run = run_child({executable, "--gtest_filter=" + name, "--gtest_color=no"}, o);
  close(nonce_pipe[0]);
  t.seconds = run.seconds;
  t.output = run.output;
  t.disk_exceeded = run.disk_exceeded;
  t.status = judge_sealed_report(report.contents(1 << 20), nonce, name, run, &t.why);
  sandbox.finish(scratch);
  return t;
}

std::vector<SealedTest> run_sealed_tests(const std::vector<SealedRun>& runs, const Sandbox& sandbox,
                                         const std::vector<std::string>& environment) {
  std::vector<SealedTest> results(runs.size());
  // Without a uid of its own per lane, ending one test's user would end the others': one lane.
  const int lanes = sandbox.protects() ? std::max(1, std::min<int>(sandbox.jobs, int(runs.size()))) : 1;
  std::atomic<size_t> next{0};
  auto lane_work = [&](int k) {
    Sandbox mine = sandbox.lane(k);
    for (size_t i; (i = next++) < runs.size();)
      results[i] = run_sealed_test(runs[i].executable, runs[i].name, mine, runs[i].wall_seconds,
                                   environment);
  };
  if (lanes == 1) {
    lane_work(0);
  } else {
    std::vector<std::thread> threads;
    for (int k = 0; k < lanes; ++k) threads.emplace_back(lane_work, k);
    for (std::thread& t : threads) t.join();
    // The disk is shared: a test stopped for it beside others may have paid for another's.
    Sandbox alone = sandbox.lane(0);
    for (size_t i = 0; i < runs.size(); ++i)
      if (results[i].disk_exceeded)
        results[i] = run_sealed_test(runs[i].executable, runs[i].name, alone,
                                     runs[i].wall_seconds, environment);
  }
  return results;
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
