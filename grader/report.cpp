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

void print_score_table(std::ostream& out, const std::vector<CheckResult>& results) {
  double total = 0.0, max = 0.0;
  int last_part = -1;
  char line[200];
  for (const CheckResult& r : results) {
    if (r.part != last_part) {
      out << "\nPart " << r.part << "\n";
      std::snprintf(line, sizeof line, "  %-44s %9s  %s\n", "check", "points", "result");
      out << line;
      last_part = r.part;
    }
    const char* verdict = r.skipped ? "skipped" : r.pass ? "pass" : "FAIL";
    std::snprintf(line, sizeof line, "  %-44s %9s  %-7s %5.1fs\n", r.name.c_str(),
                  points(r.score, r.max_score).c_str(), verdict, r.seconds);
    out << line;
    if (!r.pass || r.skipped) {
      std::istringstream in(r.output);
      for (std::string l; std::getline(in, l);) out << "      " << l << "\n";
    }
    total += r.score;
    max += r.max_score;
  }
  out << "\nTotal: " << points(total, max) << (all_passed(results) ? "  (all checks pass)" : "")
      << "\n";
}

nlohmann::json gradescope_results(const std::vector<CheckResult>& results, double seconds) {
  nlohmann::json j;
  double total = 0.0;
  j["tests"] = nlohmann::json::array();
  for (const CheckResult& r : results) {
    nlohmann::json t;
    t["name"] = r.name;
    t["score"] = r.score;
    t["max_score"] = r.max_score;
    t["output"] = (r.skipped ? "skipped: " : r.pass ? "pass: " : "FAIL: ") + r.output;
    t["visibility"] = "visible";
    j["tests"].push_back(t);
    total += r.score;
  }
  j["score"] = total;
  j["execution_time"] = seconds;
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

bool all_passed(const std::vector<CheckResult>& results) {
  for (const CheckResult& r : results)
    if (!r.skipped && (!r.pass || r.score < r.max_score)) return false;
  return !results.empty();
}

}  // namespace pt::grader
