#include "grader/judged_tests.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "framework/text/text_file.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

// A record larger than this is not one a test's calls make: the probe is cut off there, and the
// judge's replay then fails on the missing calls.
constexpr size_t kMaxRecordBytes = size_t(512) << 20;

// The probes and judges are built in the tree's folder for what holds the solution or judges.
std::string judge_dir(const std::string& build) { return (fs::path(build) / "secret").string(); }

/// GoogleTest's JSON writes each byte of a message as a character of its own (\u00c2\u00b1 for
/// the two bytes of ±): when every character of `text` is below 256, its bytes are those.
std::string bytes_of(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      out += char(c);
      ++i;
    } else if ((c & 0xe0) == 0xc0 && i + 1 < text.size() && c <= 0xc3) {
      out += char(((c & 0x1f) << 6) | (static_cast<unsigned char>(text[i + 1]) & 0x3f));
      i += 2;
    } else {
      return text;  // a character past 255: the text is UTF-8 already
    }
  }
  return out;
}

/// The first failure GoogleTest's JSON report of the judge holds, or "".
std::string judge_failure(const std::string& json_text) {
  try {
    nlohmann::json j = nlohmann::json::parse(json_text);
    for (const auto& suite : j.value("testsuites", nlohmann::json::array()))
      for (const auto& test : suite.value("testsuite", nlohmann::json::array()))
        for (const auto& f : test.value("failures", nlohmann::json::array()))
          return bytes_of(f.value("failure", ""));
  } catch (const std::exception&) {
  }
  return "";
}

/// Whether the judge's JSON report says the one test ran and passed.
bool judge_passed(const std::string& json_text, const std::string& gtest) {
  try {
    nlohmann::json j = nlohmann::json::parse(json_text);
    int seen = 0;
    bool ok = false;
    for (const auto& suite : j.value("testsuites", nlohmann::json::array()))
      for (const auto& test : suite.value("testsuite", nlohmann::json::array())) {
        if (suite.value("name", "") + "." + test.value("name", "") != gtest) continue;
        ++seen;
        ok = test.value("result", "") == "COMPLETED" && test.value("status", "") == "RUN" &&
             !test.contains("failures") && !test.contains("skipped");
      }
    return seen == 1 && ok;
  } catch (const std::exception&) {
    return false;
  }
}

/// Whether the judge's JSON report says the one test was skipped.
bool judge_skipped(const std::string& json_text, const std::string& gtest) {
  try {
    nlohmann::json j = nlohmann::json::parse(json_text);
    for (const auto& suite : j.value("testsuites", nlohmann::json::array()))
      for (const auto& test : suite.value("testsuite", nlohmann::json::array()))
        if (suite.value("name", "") + "." + test.value("name", "") == gtest)
          return test.value("result", "") == "SKIPPED" || test.contains("skipped");
  } catch (const std::exception&) {
  }
  return false;
}

/// A folder of the grader's own (0700) for one test's record and verdict.
struct WorkFolder {
  std::string path;
  explicit WorkFolder(const std::string& root) {
    fs::create_directories(root);
    std::string tmpl = (fs::path(root) / "judge-XXXXXX").string();
    if (mkdtemp(tmpl.data())) path = tmpl;
  }
  ~WorkFolder() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

JudgedOutcome run_one(const JudgedTest& t, const Sandbox& sandbox, double wall_seconds,
                      const std::string& work_root) {
  JudgedOutcome o;
  WorkFolder work(work_root);
  if (work.path.empty()) {
    o.message = "the grader cannot make a folder for the test's record";
    return o;
  }
  // The probe: the student's code, as the sandbox's user, writing its record to a file that
  // only this descriptor reaches (unlinked: no path to it exists).
  std::string record_path = work.path + "/record";
  int fd = open(record_path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    o.message = "the grader cannot make the test's record";
    return o;
  }
  unlink(record_path.c_str());
  std::string scratch;
  try {
    scratch = sandbox.make_scratch("test");
  } catch (const std::exception& e) {
    close(fd);
    o.message = e.what();
    return o;
  }
  ChildOptions po = sandbox.options(scratch, wall_seconds);
  po.keep_fds = {fd};
  po.limits.file_size = std::min<size_t>(po.limits.file_size ? po.limits.file_size : kMaxRecordBytes,
                                         kMaxRecordBytes);
  po.environment.push_back("PT_RECORD_FD=" + std::to_string(fd));
  ChildResult probe = run_child({t.probe, "--gtest_filter=" + t.gtest, "--gtest_color=no"}, po);
  sandbox.finish(scratch);
  o.student_output = probe.output;
  o.disk_exceeded = probe.disk_exceeded;
  o.killed_from_outside = probe.killed_from_outside;
  o.seconds = probe.seconds;
  // The record, copied to a file of the grader's own for the judge.
  std::string replay_path = work.path + "/replay";
  {
    std::ofstream out(replay_path, std::ios::binary);
    char buf[1 << 16];
    off_t at = 0;
    size_t total = 0;
    for (ssize_t n; total < kMaxRecordBytes && (n = pread(fd, buf, sizeof buf, at)) > 0; at += n) {
      out.write(buf, n);
      total += size_t(n);
    }
  }
  close(fd);
  // The judge: no student code, the grader's own user, the record replayed.
  std::string verdict_path = work.path + "/verdict.json";
  ChildOptions jo;
  jo.limits.wall_seconds = wall_seconds;
  jo.limits.cpu_seconds = wall_seconds * 4 + 10;
  jo.limits.address_space = size_t(4) << 30;
  jo.working_dir = work.path;
  jo.environment.push_back("PT_REPLAY_FILE=" + replay_path);
  ChildResult judge = run_child({t.judge, "--gtest_filter=" + t.gtest, "--gtest_color=no",
                                 "--gtest_output=json:" + verdict_path},
                                jo);
  o.seconds += judge.seconds;
  std::string verdict;
  try {
    verdict = read_text_file(verdict_path);
  } catch (const std::exception&) {
  }
  // The probe must have ended by itself: answers given before a crash or a hang do not count.
  const bool probe_ended = probe.started && !probe.timed_out && !probe.disk_exceeded &&
                           probe.signal == 0 && !probe.unknown_status;
  o.pass = probe_ended && judge.ok() && judge_passed(verdict, t.gtest);
  if (o.pass) return o;
  // A test the judge skipped could not run here (its scene is not there): the judge skips
  // before any call into the part, so the probe, on the same machine, skipped as well.
  if (judge_skipped(verdict, t.gtest)) {
    o.skipped = true;
    o.message = gtest_skip_reason(judge.output);
    if (o.message.empty()) o.message = "the test could not run here";
    return o;
  }
  std::string failure = judge_failure(verdict);
  if (!failure.empty()) {
    o.message = failure;
  } else if (judge.exit_code == 3) {
    o.message = "your code made calls this test does not make (before or after it)";
  } else if (!judge.ok() && probe_ended) {
    o.message = "the judge could not replay your code's answers (it " + judge.describe() + ")";
  }
  if (!probe_ended) {
    std::string how = probe.describe();
    o.message += (o.message.empty() ? "" : "\n") + std::string("your code ") + how +
                 (probe.timed_out ? ": an endless loop, or far too slow?" : "");
    // Why it did not start is the grader's own words (which step of starting it, and errno),
    // not the student's output.
    if (!probe.started && !probe.errors.empty()) o.message += " (" + probe.errors + ")";
  }
  if (o.message.empty()) o.message = "failed";
  return o;
}

}  // namespace

std::string gtest_skip_reason(const std::string& output) {
  std::istringstream in(output);
  std::string reason;
  bool in_reason = false;
  for (std::string line; std::getline(in, line);) {
    if (!in_reason) {
      // GoogleTest's "file:line: Skipped" line, then the message the test streamed.
      const size_t at = line.rfind(": Skipped");
      in_reason = at != std::string::npos && at + 9 == line.size();
      continue;
    }
    if (line.rfind("[  ", 0) == 0) break;  // the next status line
    reason += (reason.empty() ? "" : "\n") + line;
  }
  while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) reason.pop_back();
  return reason;
}

bool has_judges(const std::string& build_dir, int part) {
  std::error_code ec;
  const std::string prefix = "judge_part" + std::to_string(part) + "_step";
  for (const fs::directory_entry& e : fs::directory_iterator(judge_dir(build_dir), ec))
    if (e.path().filename().string().rfind(prefix, 0) == 0) return true;
  return false;
}

std::vector<JudgedTest> list_judged_tests(int part, const std::string& probe_build,
                                          const std::string& judge_build) {
  std::vector<JudgedTest> all;
  const std::regex name("judge_part" + std::to_string(part) + "_(step([0-9]+)_[a-z0-9_]+_test)");
  std::vector<fs::path> judges;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(judge_dir(judge_build), ec))
    if (std::regex_match(e.path().filename().string(), name)) judges.push_back(e.path());
  std::sort(judges.begin(), judges.end());
  for (const fs::path& judge : judges) {
    std::smatch m;
    std::string file = judge.filename().string();
    std::regex_match(file, m, name);
    const std::string probe = (fs::path(judge_dir(probe_build)) /
                               ("probe_part" + std::to_string(part) + "_" + m[1].str())).string();
    for (const std::string& gtest : list_gtest_tests(judge.string(), 60.0)) {
      JudgedTest t;
      t.part = part;
      t.step = std::stoi(m[2].str());
      t.gtest = gtest;
      t.name = "part" + std::to_string(part) + ".step" + m[2].str() + "." + gtest;
      t.probe = probe;
      t.judge = judge.string();
      all.push_back(t);
    }
  }
  return all;
}

std::vector<JudgedOutcome> run_judged_tests(const std::vector<JudgedTest>& tests,
                                            const Sandbox& sandbox, double wall_seconds,
                                            const std::string& work_dir,
                                            const std::vector<double>& expected_seconds) {
  std::vector<JudgedOutcome> results(tests.size());
  const int lanes = std::max(1, std::min<int>(sandbox.jobs, int(tests.size())));
  std::vector<size_t> order(tests.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (expected_seconds.size() == tests.size())
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return expected_seconds[a] > expected_seconds[b];
    });
  std::atomic<size_t> next{0};
  auto lane_work = [&](int k) {
    Sandbox mine = sandbox.protects() ? sandbox.lane(k) : sandbox;
    for (size_t n; (n = next++) < tests.size();)
      results[order[n]] = run_one(tests[order[n]], mine, wall_seconds, work_dir);
  };
  if (lanes == 1) {
    lane_work(0);
  } else {
    std::vector<std::thread> threads;
    for (int k = 0; k < lanes; ++k) threads.emplace_back(lane_work, k);
    for (std::thread& t : threads) t.join();
    Sandbox alone = sandbox.protects() ? sandbox.lane(0) : sandbox;
    for (size_t i = 0; i < tests.size(); ++i)
      if (results[i].disk_exceeded) results[i] = run_one(tests[i], alone, wall_seconds, work_dir);
  }
  for (size_t i = 0; i < tests.size(); ++i) {
    if (!results[i].killed_from_outside) continue;
    results[i] = run_one(tests[i], sandbox.lane(0), wall_seconds, work_dir);
    if (results[i].killed_from_outside)
      throw std::runtime_error(tests[i].name + " was killed twice by no limit of its own (from "
                               "outside its sandbox): the grader's error, not a verdict");
  }
  return results;
}

}  // namespace pt::grader
