#include "grader/batch.h"

#include <sched.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>

#include "grader/process/child_process.h"
#include "framework/text/text_file.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

/// Whether this process may make a mount namespace (tried in a child, so nothing changes here).
bool can_make_mount_namespaces() {
  pid_t p = fork();
  if (p == 0) _exit(unshare(CLONE_NEWNS) == 0 ? 0 : 1);
  int st = 0;
  return p > 0 && waitpid(p, &st, 0) == p && WIFEXITED(st) && WEXITSTATUS(st) == 0;
}

/// `cp -a FROM TO` (modes, owners and times kept: the build tree stays up to date).
void copy_tree(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::remove_all(to, ec);
  ChildResult c = run_child({"cp", "-a", from.string(), to.string()}, 1800.0);
  if (!c.ok()) throw std::runtime_error("cp -a " + from.string() + " " + to.string() + " " + c.describe() + ": " + c.output);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

nlohmann::json not_graded(const std::string& why) {
  return {{"score", 0},
          {"output", "The autograder could not grade this submission (" + why +
                         "). This is not a verdict on your code: please tell the course staff."},
          {"tests", nlohmann::json::array()}};
}

}  // namespace

std::vector<BatchScore> scores_of(const std::string& submission, const nlohmann::json& results) {
  std::vector<BatchScore> rows;
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array())) {
    BatchScore r;
    r.submission = submission;
    r.step = t.value("name", "");
    if (t.contains("extra_data")) r.part = t["extra_data"].value("part", 0);
    r.points = t.value("score", 0.0);
    r.max_points = t.value("max_score", 0.0);
    rows.push_back(r);
  }
  return rows;
}

std::string scores_csv(const std::vector<BatchScore>& rows) {
  std::string s = "submission,part,step,points,max_points\n";
  char num[64];
  for (const BatchScore& r : rows) {
    std::snprintf(num, sizeof num, ",%.6g,%.6g\n", r.points, r.max_points);
    s += csv_field(r.submission) + "," + std::to_string(r.part) + "," + csv_field(r.step) + num;
  }
  return s;
}

int grade_batch(const BatchOptions& options) {
  auto start = std::chrono::steady_clock::now();
  AutogradeLayout L = AutogradeLayout::under(options.root);
  fs::path dir = fs::absolute(options.submissions);
  if (!fs::is_regular_file(L.student_list()) || !fs::is_regular_file(L.grader())) {
    std::cerr << "grader batch: " << L.root.string()
              << " is not set up (run the bundle's setup.sh with PT_AUTOGRADER_ROOT there first)\n";
    return 2;
  }
  if (!fs::is_directory(dir)) {
    std::cerr << "grader batch: " << dir.string() << ": no such folder of submissions\n";
    return 2;
  }
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (e.is_directory() && !e.is_symlink()) {
      names.push_back(name);
    } else {
      std::cerr << "grader batch: " << e.path().string() << ": not a folder, not graded\n";
    }
  }
  std::sort(names.begin(), names.end());
  fs::path out = options.out_dir.empty() ? fs::path(dir.string() + "-results") : fs::absolute(options.out_dir);
  fs::create_directories(out);
  fs::permissions(out, fs::perms(0700));

  // Everything a run needs besides its own results sits under trees/ (root's alone, 0700): the
  // set-up tree as setup.sh left it, each submission's copy (no student's code may read another
  // student's files), each run's copy of the tree.
  fs::path trees = L.root / "pt" / "trees";
  fs::create_directories(trees);
  fs::permissions(trees, fs::perms(0700));
  fs::path pristine = trees / "set-up";
  if (!fs::exists(pristine)) {
    copy_tree(L.project, trees / "set-up.partial");
    fs::rename(trees / "set-up.partial", pristine);
  }
  const bool side_by_side = can_make_mount_namespaces();
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  int jobs = options.jobs > 0 ? options.jobs : cores;
  if (!side_by_side) jobs = 1;
  jobs = std::max(1, std::min<int>(jobs, int(names.size())));
  const int per_run = std::max(1, cores / jobs);  // tests at once and build jobs of each run
  std::cerr << "grader batch: " << names.size() << " submissions, " << jobs << " at once"
            << (side_by_side ? "" : " (no mount namespaces here: one at a time)") << "\n";

  std::vector<nlohmann::json> results(names.size());
  std::atomic<size_t> next{0};
  std::mutex print;
  auto grade_one = [&](size_t i, int k, bool again) {
    const std::string& name = names[i];
    nlohmann::json r;
    try {
      fs::path submission = trees / ("submission-" + name);
      copy_tree(dir / name, submission);
      fs::path tree = trees / ("tree-" + std::to_string(k));
      if (side_by_side) {
        copy_tree(pristine, tree);
      } else {
        copy_tree(pristine, L.project);  // one at a time: the tree itself, made fresh
      }
      fs::create_directories(out / name);
      fs::permissions(out / name, fs::perms(0700));
      fs::path file = out / name / "results.json";
      fs::remove(file);
      std::vector<std::string> argv = {options.grader_exe, "autograde", "--root", L.root.string(),
                                       "--submission", submission.string(), "--results", file.string(),
                                       "--slot", std::to_string(k * per_run), "--jobs",
                                       std::to_string(per_run), "--build-jobs", std::to_string(per_run)};
      if (side_by_side) argv.insert(argv.end(), {"--tree", tree.string()});
      if (!options.parts.empty()) {
        std::string list;
        for (int p : options.parts) list += (list.empty() ? "" : ",") + std::to_string(p);
        argv.insert(argv.end(), {"--parts", list});
      }
      if (options.tuning.max_check_seconds > 0)
        argv.insert(argv.end(), {"--max-check-seconds", std::to_string(options.tuning.max_check_seconds)});
      if (options.tuning.quote_student_lines) argv.push_back("--quote-student-lines");
      ChildOptions o;
      o.limits.wall_seconds = 6 * 3600.0;  // the run's own limits bound it; this bounds the grader
      o.limits.max_output = 256 << 10;
      ChildResult c = run_child(argv, o);
      std::error_code ec;
      fs::remove_all(submission, ec);
      if (side_by_side) fs::remove_all(tree, ec);
      try {
        r = nlohmann::json::parse(read_text_file(file));
      } catch (const std::exception&) {
        r = not_graded("the grader " + c.describe() + ": " + tail_lines(c.output, 3));
        std::ofstream(file) << r.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
      }
    } catch (const std::exception& e) {
      r = not_graded(e.what());
      std::error_code ec;
      fs::create_directories(out / name, ec);
      std::ofstream(out / name / "results.json") << r.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    double max = 0.0;
    for (const nlohmann::json& t : r.value("tests", nlohmann::json::array())) max += t.value("max_score", 0.0);
    {
      std::lock_guard<std::mutex> lock(print);
      char line[512];
      std::snprintf(line, sizeof line, "%s: %g of %g points", name.c_str(), r.value("score", 0.0), max);
      std::cout << line << (r.value("tests", nlohmann::json::array()).empty() ? " (not graded: see its results.json)" : "")
                << (again ? " (graded again alone)" : "") << std::endl;
    }
    results[i] = r;
  };
  std::vector<std::thread> threads;
  for (int k = 0; k < jobs; ++k)
    threads.emplace_back([&, k] {
      for (size_t i; (i = next++) < names.size();) grade_one(i, k, false);
    });
  for (std::thread& t : threads) t.join();
  // The disk limit watches free space, which runs side by side share: a submission with a check
  // stopped for the disk may have paid for another's, so it is graded again alone, and only that
  // grade counts.
  if (jobs > 1) {
    for (size_t i = 0; i < names.size(); ++i)
      if (results[i].dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).find("wrote more to disk than it is allowed") != std::string::npos)
        grade_one(i, 0, true);
  }

  std::vector<BatchScore> rows;
  for (size_t i = 0; i < names.size(); ++i) {
    std::vector<BatchScore> r = scores_of(names[i], results[i]);
    rows.insert(rows.end(), r.begin(), r.end());
  }
  std::ofstream(out / "scores.csv") << scores_csv(rows);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "grader batch: " << names.size() << " submissions in " << int(seconds + 0.5)
            << " s; results in " << out.string() << ", every step's points in "
            << (out / "scores.csv").string() << "\n";
  return 0;
}

}  // namespace pt::grader
