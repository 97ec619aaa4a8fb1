#include "grader/report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace pt::grader {
namespace {

std::string points(double score, double max) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g/%g", std::round(score * 10.0) / 10.0, max);
  return buf;
}

}  // namespace

std::string skipped_summary(int checks, double weight) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "%d check%s could not run here (the steps' messages say why: most often the "
                "course's scenes are not at ../shared/scenes/cs184, beside the project). Not "
                "counted, not failed: %g points ungraded, decided by their steps' checks that ran "
                "instead. Gradescope runs every check.",
                checks, checks == 1 ? "" : "s", std::round(weight * 10.0) / 10.0);
  return buf;
}

void print_score_table(std::ostream& out, const std::vector<PartResult>& results) {
  double total = 0.0, max = 0.0, open = 0.0, skipped_points = 0.0;
  int skipped = 0;
  bool alone = !results.empty();
  char line[240];
  for (const PartResult& p : results) {
    out << "\nPart " << p.part << "\n";
    if (!p.rests_on.empty()) out << p.rests_on << "\n";
    if (!p.built) {
      std::istringstream in(p.build_output);
      for (std::string l; std::getline(in, l);) out << "  " << l << "\n";
    }
    std::snprintf(line, sizeof line, "  %-34s %9s  %-6s %s\n", "step", "points", "result", "checks");
    out << line;
    for (const StepResult& s : p.steps) {
      const char* verdict = s.passed() ? "pass" : "FAIL";
      std::string checks = s.counted() == 0
                               ? "none counted"
                               : std::to_string(s.counted() - s.failed()) + " of " +
                                     std::to_string(s.counted()) + " pass";
      double seconds = 0.0;
      for (const CheckResult& c : s.checks) seconds += c.seconds;
      std::snprintf(line, sizeof line, "  %-34s %9s  %-6s %-14s %5.1fs\n", s.name.c_str(),
                    points(s.score, s.max_score).c_str(), verdict, checks.c_str(), seconds);
      out << line;
      if ((!s.passed() || s.failed() > 0 || s.skipped() > 0) && p.built) {
        std::istringstream in(s.message);
        for (std::string l; std::getline(in, l);) out << "      " << l << "\n";
      }
      total += s.score;
      max += s.max_score;
    }
    for (const std::string& u : p.unassigned)
      out << "  (not scored: the test " << u << " names no step of part " << p.part << ")\n";
    if (p.open_checks > 0) {
      std::string parts;
      for (size_t i = 0; i < p.failing_parts_run.size(); ++i)
        parts += (i == 0 ? "" : i + 1 == p.failing_parts_run.size() ? " and " : ", ") +
                 std::string("Part ") + std::to_string(p.failing_parts_run[i]);
      out << "  On Gradescope, which grades Part " << p.part
          << " with the course's own other parts: between " << points(p.score(), p.max_score())
          << " and " << points(p.score() + p.open_points, p.max_score()) << " (" << p.open_checks
          << " failing check" << (p.open_checks == 1 ? "" : "s") << " here ran your " << parts
          << ", which fails).\n";
    }
    for (int k : p.changed_parts_run)
      out << "  Part " << k << " changed since it was last graded, as failing: grade it again "
          << "(grader --part " << k << ") to know how it stands now.\n";
    open += p.open_points;
    skipped += p.skipped_checks();
    skipped_points += p.skipped_points();
    alone = alone && p.graded_alone;
  }
  out << "\nTotal: " << points(total, max) << (all_passed(results) ? "  (every step passes)" : "")
      << "\n";
  if (skipped > 0)
    out << skipped_summary(skipped, skipped_points) << "\n";
  if (alone) {
    out << "Graded as Gradescope grades it: each part with the course's own other parts.\n";
  } else if (open > 0.0) {
    out << "Gradescope grades each part with the course's own other parts, so its total is "
           "between "
        << points(total, max) << " and " << points(total + open, max)
        << ": fix the earlier part that fails and grade again to know it.\n";
  } else {
    out << "Gradescope grades each part with the course's own other parts; no failing check here "
           "ran a failing part of yours, so it gives this total (its renders are of scenes "
           "varied for each submission: correct code passes both).\n";
  }
}

namespace {

// What results.json may carry, whoever wrote it: a submission's code must not be able to carry
// anything out of the grader in its messages (docs/grading.md, "What reaches the student").
constexpr size_t kStepOutputChars = 2000;
constexpr size_t kCheckOutputChars = 1200;
constexpr size_t kRunOutputChars = 6000;

std::string capped(const std::string& text, size_t limit) {
  if (text.size() <= limit) return text;
  return text.substr(0, limit) + " [... " + std::to_string(text.size() - limit) + " more characters not shown]";
}

}  // namespace

nlohmann::json gradescope_results(const std::vector<PartResult>& results, const RunInfo& info) {
  nlohmann::json j;
  double total = 0.0;
  std::string output;
  j["tests"] = nlohmann::json::array();
  nlohmann::json parts = nlohmann::json::array();
  bool built = true;
  for (const PartResult& p : results) {
    parts.push_back(p.part);
    built = built && p.built;
    if (!p.rests_on.empty()) output += p.rests_on + "\n";
    if (!p.built) output += p.build_output + "\n";
    for (const StepResult& s : p.steps) {
      nlohmann::json t;
      t["name"] = s.name;
      t["number"] = std::to_string(s.part) + "." + std::to_string(s.step);
      t["score"] = s.score;
      t["max_score"] = s.max_score;
      t["status"] = s.passed() ? "passed" : "failed";
      t["output"] = capped(s.message, kStepOutputChars);
      t["visibility"] = "visible";
      nlohmann::json checks = nlohmann::json::array();
      for (const CheckResult& c : s.checks) {
        const std::string said = c.todo.empty() ? c.output : c.output + "\n" + c.todo;
        // No check's time: the student's code chooses how long it takes, and a time to the
        // microsecond per check would carry its choice out (the run's time is whole seconds).
        nlohmann::json cj = {{"name", c.name},
                             {"kind", c.kind},
                             {"status", c.skipped ? "skipped" : c.pass ? "passed" : "failed"},
                             {"output", capped(said, kCheckOutputChars)}};
        if (c.kind == "render") cj["seed"] = c.seed;
        checks.push_back(cj);
      }
      size_t dot = s.name.rfind('.');
      t["extra_data"] = {{"part", s.part},
                         {"step", s.step},
                         {"step_name", dot == std::string::npos ? s.name : s.name.substr(dot + 1)},
                         {"checks", checks}};
      j["tests"].push_back(t);
      total += s.score;
    }
  }
  int skipped = 0;
  double skipped_points = 0.0;
  for (const PartResult& p : results) {
    skipped += p.skipped_checks();
    skipped_points += p.skipped_points();
  }
  if (skipped > 0) output += skipped_summary(skipped, skipped_points) + "\n";
  j["score"] = total;
  j["execution_time"] = std::round(info.seconds);
  j["output"] = capped(output, kRunOutputChars);
  j["extra_data"] = {{"isolated", info.isolated},
                     {"seed_offset", info.seed_offset},
                     {"parts", parts},
                     {"build", built ? "ok" : "failed"},
                     {"skipped_checks", skipped},
                     {"skipped_points", skipped_points}};
  return j;
}

std::string validate_gradescope(const nlohmann::json& j) {
  if (!j.is_object()) return "the results are not a JSON object";
  if (j.contains("score") && !j["score"].is_number()) return "\"score\" is not a number";
  if (j.contains("execution_time") && !j["execution_time"].is_number())
    return "\"execution_time\" is not a number";
  if (!j.contains("tests") && !j.contains("score")) return "neither \"score\" nor \"tests\"";
  if (!j.contains("tests")) return "";
  if (!j["tests"].is_array()) return "\"tests\" is not an array";
  double sum = 0.0;
  for (size_t i = 0; i < j["tests"].size(); ++i) {
    const nlohmann::json& t = j["tests"][i];
    std::string where = "tests[" + std::to_string(i) + "]";
    if (!t.is_object()) return where + " is not an object";
    if (t.contains("name") && !t["name"].is_string()) return where + ".name is not a string";
    if (!t.contains("score") || !t["score"].is_number()) return where + ".score is not a number";
    if (t.contains("max_score") && !t["max_score"].is_number())
      return where + ".max_score is not a number";
    if (t.contains("output") && !t["output"].is_string()) return where + ".output is not a string";
    if (t.contains("status") && t["status"] != "passed" && t["status"] != "failed")
      return where + ".status is not passed or failed";
    if (t.contains("visibility")) {
      std::string v = t["visibility"].is_string() ? t["visibility"].get<std::string>() : "";
      if (v != "hidden" && v != "after_due_date" && v != "after_published" && v != "visible")
        return where + ".visibility is not one of hidden, after_due_date, after_published, visible";
    }
    sum += t["score"].get<double>();
  }
  if (j.contains("score") && std::fabs(j["score"].get<double>() - sum) > 1e-6 * (1.0 + sum))
    return "\"score\" is not the sum of the tests' scores";
  return "";
}

bool all_passed(const std::vector<PartResult>& results) {
  if (results.empty()) return false;
  for (const PartResult& p : results) {
    if (!p.built || p.steps.empty()) return false;
    for (const StepResult& s : p.steps)
      if (!s.passed()) return false;
  }
  return true;
}

}  // namespace pt::grader
