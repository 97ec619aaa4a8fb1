#include "grader/mutants.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "grader/process/child_process.h"
#include "framework/text/text_file.h"
#include "grader/scratch_tree.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace pt::grader {
namespace {

const std::regex kStepName(R"(^part\d+\.step\d+\.[A-Za-z0-9_]+$)");

/// "partN.stepK.NAME" of a check named "partN.stepK.NAME.more" (or the name itself).
std::string step_of_check(const std::string& check) {
  size_t dots = 0;
  for (size_t i = 0; i < check.size(); ++i)
    if (check[i] == '.' && ++dots == 3) return check.substr(0, i);
  return check;
}

/// The message's first lines on one line, cut to `width` characters.
std::string one_line(const std::string& text, size_t width = 150) {
  std::string s;
  std::istringstream in(text);
  int lines = 0;
  for (std::string line; std::getline(in, line) && lines < 2;) {
    size_t a = line.find_first_not_of(" \t");
    if (a == std::string::npos) continue;
    if (!s.empty()) s += " / ";
    s += line.substr(a);
    ++lines;
  }
  if (s.size() > width) s = s.substr(0, width - 3) + "...";
  return s;
}

std::string points(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

std::string text_of(const json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

/// The per-check results file main's grader writes: one test for the part's CTest label (its
/// failures listed by name), one a render.
void per_check_losses(const json& test, std::vector<StepLoss>* out) {
  std::string name = text_of(test, "name"), output = text_of(test, "output");
  double score = test.value("score", 0.0), max_score = test.value("max_score", 0.0);
  if (name.size() > 6 && name.compare(name.size() - 6, 6, ".tests") == 0) {
    std::smatch m;
    std::regex counts(R"((\d+) of (\d+) tests passed)");
    int counted = std::regex_search(output, m, counts) ? std::stoi(m[2]) : 0;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) {
      size_t at = line.find("failed: ");
      if (at == std::string::npos) continue;
      std::string check = line.substr(at + 8);
      std::string step = step_of_check(check);
      double share = counted > 0 ? max_score / counted : max_score;
      auto it = std::find_if(out->begin(), out->end(), [&](const StepLoss& l) { return l.step == step; });
      if (it == out->end()) out->push_back({step, share, 0.0, "failed: " + check});
      else it->lost += share;
    }
    if (counted == 0 && score < max_score) out->push_back({name, max_score - score, max_score, output});
    return;
  }
  if (score < max_score - 1e-9) out->push_back({name, max_score - score, max_score, output});
}

}  // namespace

std::vector<MutantSpec> read_mutant_index(const std::string& path) {
  json doc;
  try {
    doc = json::parse(read_text_file(path));
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a mutant index (" + e.what() + ")");
  }
  if (!doc.contains("mutants") || !doc["mutants"].is_array())
    throw std::runtime_error(path + ": no \"mutants\" array");
  std::vector<MutantSpec> specs;
  for (size_t i = 0; i < doc["mutants"].size(); ++i) {
    const json& m = doc["mutants"][i];
    MutantSpec s;
    s.name = text_of(m, "name");
    s.patch = text_of(m, "patch");
    s.part = m.value("part", 0);
    s.step = text_of(m, "step");
    s.bug = text_of(m, "bug");
    s.cause = text_of(m, "cause");
    s.hint = text_of(m, "hint");
    std::string where = path + ": mutant " + std::to_string(i + 1) + " (" + s.name + ")";
    if (s.name.empty() || s.patch.empty()) throw std::runtime_error(where + ": needs a name and a patch");
    if (s.part < 1 || s.part > 5) throw std::runtime_error(where + ": part must be 1-5");
    if (!std::regex_match(s.step, kStepName) || s.step.rfind("part" + std::to_string(s.part) + ".", 0) != 0)
      throw std::runtime_error(where + ": step \"" + s.step + "\" is not a step of part " +
                               std::to_string(s.part) + " (partN.stepK.NAME)");
    try {
      std::regex(s.hint, std::regex::icase);
    } catch (const std::regex_error&) {
      throw std::runtime_error(where + ": the hint \"" + s.hint + "\" is not a regular expression");
    }
    specs.push_back(s);
  }
  return specs;
}

std::vector<StepLoss> step_losses(const json& results) {
  std::vector<StepLoss> losses;
  if (!results.contains("tests") || !results["tests"].is_array()) return losses;
  bool by_step = false;
  for (const json& t : results["tests"])
    if (std::regex_match(text_of(t, "name"), kStepName)) by_step = true;
  for (const json& t : results["tests"]) {
    if (!by_step) {
      per_check_losses(t, &losses);
      continue;
    }
    double score = t.value("score", 0.0), max_score = t.value("max_score", 0.0);
    if (score < max_score - 1e-9)
      losses.push_back({text_of(t, "name"), max_score - score, max_score, text_of(t, "output")});
  }
  return losses;
}

MutantOutcome judge_mutant(const MutantSpec& spec, const std::vector<StepLoss>& losses) {
  MutantOutcome o;
  o.spec = spec;
  o.losses = losses;
  const StepLoss* own = nullptr;
  // A grader that reports renders by their own names, not under a step (main's before the
  // rubric by step), leaves them unattributed: listed, but neither "elsewhere" nor its own step.
  size_t attributed = 0;
  for (const StepLoss& l : losses) {
    if (l.step == spec.step) own = &l;
    if (std::regex_match(l.step, kStepName)) ++attributed;
  }
  bool elsewhere = attributed > (own ? 1u : 0u);
  if (losses.empty()) {
    o.verdict = "PASSES";
  } else if (!own && attributed == 0) {
    o.verdict = "RENDERS ONLY";
    o.message = losses.front().message;
  } else if (!own) {
    o.verdict = "WRONG STEP";
    o.message = losses.front().message;
  } else {
    o.message = own->message;
    // The mutant's own name is in the paths the message shows (its diff image): not a hint.
    std::string said = own->message;
    for (size_t at; (at = said.find(spec.name)) != std::string::npos;) said.erase(at, spec.name.size());
    bool true_hint = std::regex_search(said, std::regex(spec.hint, std::regex::icase));
    // A bug that costs more than its step is worth: the step loses everything and the rest
    // stays where it shows, each such step naming the mutant's (grader/step_at_fault.h).
    bool spent = own->lost >= own->max_score - 1e-6;
    for (const StepLoss& l : losses)
      if (&l != own && std::regex_match(l.step, kStepName))
        spent = spent && l.message.find(spec.step) != std::string::npos;
    o.verdict = elsewhere && !spent ? "ALSO ELSEWHERE"
                : !true_hint            ? "hint?"
                : elsewhere             ? "OVERFLOW"
                                        : "ok";
  }
  return o;
}

std::vector<MutantOutcome> run_mutants(const MutantRunOptions& options, std::ostream& log) {
  std::vector<MutantSpec> all = read_mutant_index(options.index_path);
  // In the order --only names them (so a run can put one mutant of each part first), each
  // fragment's matches in the index's order; every mutant once.
  std::vector<MutantSpec> specs;
  std::set<std::string> taken;
  if (options.only.empty()) specs = all;
  for (const std::string& o : options.only)
    for (const MutantSpec& s : all)
      if (s.name.find(o) != std::string::npos && taken.insert(s.name).second) specs.push_back(s);
  if (specs.empty()) throw std::runtime_error("no mutant of " + options.index_path + " matches --only");
  fs::path index_dir = fs::path(options.index_path).parent_path();
  fs::path work = fs::absolute(options.work_dir);
  fs::create_directories(work / "results");

  if (options.report_only) {
    // The results an earlier (perhaps interrupted) run left, judged again; a mutant without
    // any is "not run".
    std::vector<MutantOutcome> outcomes;
    for (const MutantSpec& spec : specs) {
      fs::path json_path = work / "results" / (spec.name + ".json");
      MutantOutcome o;
      o.spec = spec;
      o.verdict = "not run";
      if (fs::exists(json_path)) {
        try {
          o = judge_mutant(spec, step_losses(json::parse(read_text_file(json_path))));
        } catch (const std::exception& e) {
          o.verdict = "ERROR";
          o.message = json_path.string() + ": " + e.what();
        }
      }
      outcomes.push_back(o);
    }
    return outcomes;
  }
  ChildResult help = run_child({options.grader_exe, "--help"}, 60.0);
  const bool isolated = options.isolated && help.output.find("--isolated") != std::string::npos;
  log << "grader mutants: " << specs.size() << " mutants, " << options.jobs
      << " at a time, scratch trees in " << work.string()
      << (isolated ? ", graded with --isolated"
                  : options.isolated ? ", graded without --isolated (this grader has none)"
                                     : ", graded without --isolated (--no-isolated)")
      << "\n";

  std::vector<MutantOutcome> outcomes(specs.size());
  std::atomic<size_t> next{0};
  std::mutex mutex;
  size_t done = 0;
  auto worker = [&](int k) {
    ScratchTree tree(options.source_dir, (work / ("tree-" + std::to_string(k))).string());
    std::string setup_error;
    try {
      tree.sync();
      tree.configure({"-DPT_SOLUTION_DIR=" + tree.source_dir()});
    } catch (const std::exception& e) {
      setup_error = e.what();
    }
    for (size_t i; (i = next++) < specs.size();) {
      const MutantSpec& spec = specs[i];
      auto start = std::chrono::steady_clock::now();
      MutantOutcome o;
      o.spec = spec;
      try {
        if (!setup_error.empty()) throw std::runtime_error(setup_error);
        tree.sync();
        tree.apply((index_dir / spec.patch).string());
        fs::path json_path = work / "results" / (spec.name + ".json");
        fs::remove(json_path);
        std::vector<std::string> argv = {
            options.grader_exe, "--part", std::to_string(spec.part), "--source", tree.root(),
            "--build", tree.build_dir(), "--pathtracer", tree.build_dir() + "/app/pathtracer",
            "--json", json_path.string(), "--out", (work / "results" / spec.name).string()};
        if (isolated) argv.push_back("--isolated");
        ChildResult c = run_child(argv, 3600.0);
        std::ofstream(work / "results" / (spec.name + ".log")) << command_line(argv) << "\n" << c.output;
        if (c.exit_code != 0 && c.exit_code != 1)
          throw std::runtime_error("the grader " + c.describe() + ": " + tail_lines(c.output, 4));
        json results = json::parse(read_text_file(json_path));
        bool build_failed = results.contains("extra_data") && results["extra_data"].is_object() &&
                            results["extra_data"].value("build", "") == "failed";
        if (results.contains("tests"))
          for (const json& t : results["tests"])
            if (text_of(t, "name") == "part" + std::to_string(spec.part) + ".build" &&
                text_of(t, "output").find("built") == std::string::npos)
              build_failed = true;
        o = judge_mutant(spec, step_losses(results));
        if (build_failed) {
          o.verdict = "BUILD";
          o.message = "the mutant does not build: see " + (work / "results" / (spec.name + ".log")).string();
        }
      } catch (const std::exception& e) {
        o.verdict = "ERROR";
        o.message = e.what();
      }
      tree.restore();
      o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::lock_guard<std::mutex> lock(mutex);
      outcomes[i] = o;
      log << "[" << ++done << "/" << specs.size() << "] " << spec.name << ": " << o.verdict << " ("
          << points(o.seconds) << " s)\n" << std::flush;
    }
  };
  std::vector<std::thread> threads;
  int jobs = std::max(1, std::min<int>(options.jobs, int(specs.size())));
  for (int k = 0; k < jobs; ++k) threads.emplace_back(worker, k);
  for (std::thread& t : threads) t.join();
  return outcomes;
}

void print_rule_table(std::ostream& out, const Manifest& manifest,
                      const std::vector<MutantOutcome>& outcomes) {
  out << "\nrule                                                  mutant                          "
         "verdict         names the rule\n";
  int rules = 0, broken = 0;
  for (const PartSpec& part : manifest.parts)
    for (const StepSpec& step : part.steps)
      for (const Rule& rule : step.rules) {
        const std::string name = rule.full_name(step.full_name());
        bool any = false;
        for (const std::string& m : rule.mutants)
          for (const MutantOutcome& o : outcomes) {
            if (o.spec.name != m) continue;
            any = true;
            const bool named = o.message.find("#" + rule.id + ":") != std::string::npos;
            char line[400];
            std::snprintf(line, sizeof line, "%-53s %-31s %-15s %s\n", name.c_str(), m.c_str(),
                          o.verdict.c_str(), named ? "yes" : "no");
            out << line;
          }
        ++rules;
        broken += any ? 1 : 0;
      }
  out << broken << " of " << rules << " rules broken by a mutant of this run\n";
}

void print_mutant_table(std::ostream& out, const std::vector<MutantOutcome>& outcomes,
                        double seconds) {
  size_t w_name = 6, w_step = 12;
  for (const MutantOutcome& o : outcomes) {
    w_name = std::max(w_name, o.spec.name.size());
    w_step = std::max(w_step, o.spec.step.size());
  }
  auto pad = [](const std::string& s, size_t w) { return s + std::string(w > s.size() ? w - s.size() : 0, ' '); };
  out << pad("mutant", w_name) << "  " << pad("its step", w_step) << "  " << pad("verdict", 14)
      << "  lost points in (points)  |  message\n";
  int good = 0, spent = 0;
  for (const MutantOutcome& o : outcomes) {
    std::string lost;
    for (const StepLoss& l : o.losses) {
      if (!lost.empty()) lost += ", ";
      lost += (l.step == o.spec.step ? "its step" : l.step) + " (-" + points(l.lost) + ")";
    }
    if (lost.empty()) lost = "-";
    if (o.verdict == "ok") ++good;
    if (o.verdict == "OVERFLOW") ++spent;
    out << pad(o.spec.name, w_name) << "  " << pad(o.spec.step, w_step) << "  "
        << pad(o.verdict, 14) << "  " << lost << "  |  " << one_line(o.message) << "\n";
  }
  out << good << " of " << outcomes.size()
      << " mutants lose points in their own step only, with a message that names the cause";
  if (spent > 0)
    out << "; " << spent << " lose every point of their own step, the rest staying where it "
        << "shows with a message naming their step (OVERFLOW)";
  if (seconds > 0) out << "; " << points(seconds) << " s";
  out << "\n";
}

}  // namespace pt::grader
