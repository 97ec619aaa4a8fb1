#include "grader/false_failures.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <tuple>
#include <sstream>
#include <stdexcept>

#include "grader/second_solution.h"
#include "grader/student_values.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

std::string first_line(const std::string& s) {
  std::string line = s.substr(0, s.find('\n'));
  for (char& c : line)
    if (c == '\t') c = ' ';
  return line;
}

bool wanted(const RenderCheck& check, const FalseFailureOptions& o) {
  if (o.part != 0 && check.part != o.part) return false;
  if (o.only.empty()) return true;
  for (const std::string& s : o.only)
    if (check.name.find(s) != std::string::npos) return true;
  return false;
}

}  // namespace

double binomial_tail(int n, int k, double p) {
  if (k <= 0) return 1.0;
  double below = 0.0;  // P(X < k), summed in logs so large n stays finite
  for (int i = 0; i < k && i <= n; ++i)
    below += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) +
                      i * std::log(p) + (n - i) * std::log1p(-p));
  return std::max(0.0, 1.0 - below);
}

std::vector<SeedRun> read_seed_log(const std::string& path, std::ostream& log) {
  std::vector<SeedRun> runs;
  std::ifstream in(path);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    SeedRun r;
    std::string seed, pass, seconds;
    if (!std::getline(f, r.solution, '\t') || !std::getline(f, r.render, '\t') ||
        !std::getline(f, seed, '\t') || !std::getline(f, pass, '\t') ||
        !std::getline(f, seconds, '\t')) {
      log << path << ":" << number << ": not a seed run (solution, render, seed, pass, seconds), skipped\n";
      continue;
    }
    std::getline(f, r.message);
    try {
      r.seed = std::stol(seed);
      r.seconds = std::stod(seconds);
    } catch (const std::exception&) {
      log << path << ":" << number << ": seed or seconds is not a number, skipped\n";
      continue;
    }
    r.pass = pass == "pass";
    runs.push_back(r);
  }
  return runs;
}

std::vector<SeedRun> run_false_failures(const Manifest& manifest, const GradeOptions& grade,
                                        const FalseFailureOptions& options, std::ostream& log) {
  fs::path work = fs::absolute(options.work_dir);
  fs::create_directories(work);
  std::map<std::string, GradeOptions> by_solution;
  for (const std::string& solution : options.solutions) {
    GradeOptions g = grade;
    g.out_dir = (work / ("renders-" + solution)).string();
    if (solution == "second") {
      std::string tree = make_second_solution(grade.source_dir, (work / "second").string(), log);
      build_targets(tree + "/build", {"pathtracer"}, options.build_jobs);
      g.source_dir = tree;
      g.pathtracer = tree + "/build/app/pathtracer";
    } else if (solution != "complete") {
      throw std::runtime_error("--solution: \"" + solution + "\" is neither complete nor second");
    }
    by_solution[solution] = g;
  }
  // What the log already holds counts: a run picks up where an earlier one stopped.
  std::set<std::tuple<std::string, std::string, long>> logged;
  std::map<std::pair<std::string, std::string>, double> spent;
  {
    std::ostringstream quiet;
    for (const SeedRun& r : read_seed_log(options.log_path, quiet)) {
      logged.insert({r.solution, r.render, r.seed});
      spent[{r.solution, r.render}] += r.seconds;
    }
  }
  std::ofstream out(options.log_path, std::ios::app);
  if (!out) throw std::runtime_error(options.log_path + ": cannot be written");
  // One queue per (solution, render) of its seeds not yet logged. The next render is always the
  // one that has had the least time so far, so every render gets an equal share of the machine:
  // a run stopped early has measured the cheap renders most and every render some.
  struct Queue {
    std::string solution;
    RenderCheck check;
    std::vector<uint64_t> seeds;
    size_t next = 0;
  };
  std::vector<Queue> queues;
  for (const std::string& solution : options.solutions)
    for (const PartSpec& part : manifest.parts)
      for (const RenderCheck* render : part.renders()) {
        const RenderCheck& check = *render;
        if (!wanted(check, options)) continue;
        Queue q{solution, check, {}, 0};
        for (int k = options.first; k < options.first + options.seeds; ++k) {
          uint64_t seed = check.seed + uint64_t(k);
          if (check.is_reference_seed(uint64_t(seed))) continue;  // the reference's own numbers
          if (!logged.count({solution, check.name, long(seed)})) q.seeds.push_back(seed);
        }
        queues.push_back(q);
      }
  std::vector<SeedRun> runs;
  for (;;) {
    Queue* pick = nullptr;
    for (Queue& q : queues)
      if (q.next < q.seeds.size() &&
          (!pick || spent[{q.solution, q.check.name}] < spent[{pick->solution, pick->check.name}]))
        pick = &q;
    if (!pick) break;
    RenderCheck check = pick->check;
    check.seed = pick->seeds[pick->next++];
    CheckResult r = grade_render(manifest, check, by_solution[pick->solution]);
    r.output = release_values(r.output, nullptr);  // the instructor's own log: every value
    // A course scene that is not there, or a reference not made (or not recorded) yet: nothing
    // to measure, and not correct code failing.
    const bool no_reference = !r.pass && r.output.rfind("the reference ", 0) == 0;
    if (r.skipped || no_reference) {
      log << pick->solution << " " << check.name << ": not measured: " << first_line(r.output) << "\n";
      pick->next = pick->seeds.size();
      continue;
    }
    spent[{pick->solution, check.name}] += r.seconds;
    SeedRun s{pick->solution, check.name, long(check.seed), r.pass, r.seconds,
              r.pass ? "" : first_line(r.output)};
    out << s.solution << '\t' << s.render << '\t' << s.seed << '\t' << (s.pass ? "pass" : "fail")
        << '\t' << s.seconds << '\t' << s.message << "\n" << std::flush;
    log << s.solution << " " << check.name << " seed " << s.seed << ": "
        << (s.pass ? "pass" : "FAIL: " + s.message) << "\n" << std::flush;
    runs.push_back(s);
  }
  return runs;
}

void print_false_failure_table(std::ostream& out, const Manifest& manifest,
                               const std::vector<SeedRun>& runs) {
  // The last run of each (solution, render, seed) counts.
  std::map<std::tuple<std::string, std::string, long>, const SeedRun*> last;
  for (const SeedRun& r : runs) last[{r.render, r.solution, r.seed}] = &r;
  struct Row {
    int seeds = 0, failures = 0, timeouts = 0;
    double seconds = 0.0;
    std::string example;
  };
  std::map<std::pair<std::string, std::string>, Row> rows;
  for (const auto& [key, r] : last) {
    Row& row = rows[{std::get<0>(key), std::get<1>(key)}];
    ++row.seeds;
    row.seconds += r->seconds;
    if (!r->pass) {
      ++row.failures;
      if (r->message.find("time limit") != std::string::npos) ++row.timeouts;
      if (row.example.empty()) row.example = "seed " + std::to_string(r->seed) + ": " + r->message;
    }
  }
  size_t w = 6;
  for (const auto& [key, row] : rows) w = std::max(w, key.first.size());
  auto pad = [](std::string s, size_t width) { return s + std::string(width > s.size() ? width - s.size() : 0, ' '); };
  out << pad("render", w)
      << "  solution  seeds  failures  (time limit)  rate    P(>=f | alpha)  verdict    s/render  first failure\n";
  int over = 0;
  for (const auto& [key, row] : rows) {
    double rate = row.seeds ? double(row.failures) / row.seeds : 0.0;
    double p = binomial_tail(row.seeds, row.failures, manifest.alpha);
    std::string verdict = rate <= manifest.alpha ? "ok" : (p < 0.05 ? "TOO OFTEN" : "above alpha");
    if (verdict != "ok") ++over;
    std::ostringstream line;
    line << pad(key.first, w) << "  " << pad(key.second, 8) << "  " << std::setw(5) << row.seeds
         << "  " << std::setw(8) << row.failures << "  " << std::setw(12) << row.timeouts << "  " << std::fixed << std::setprecision(3)
         << std::setw(6) << rate << "  " << std::setw(14) << std::setprecision(3) << p << "  "
         << pad(verdict, 10) << std::setw(8) << std::setprecision(2)
         << (row.seeds ? row.seconds / row.seeds : 0.0) << "  "
         << (row.example.size() > 110 ? row.example.substr(0, 107) + "..." : row.example);
    out << line.str() << "\n";
  }
  out << "family-wise alpha " << manifest.alpha << "; " << rows.size() << " (render, solution) rows, "
      << over << " above alpha; (time limit): failures that were the render running past its time "
         "limit, not the comparison\n";
}

}  // namespace pt::grader
