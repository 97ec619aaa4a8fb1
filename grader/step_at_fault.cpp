#include "grader/step_at_fault.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace pt::grader {
namespace {

std::string points_text(double p) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", p);
  return buf;
}

/// What one step gave to or took from another, for the messages.
struct Charge {
  size_t other = 0;           ///< index of the other step
  std::vector<std::string> checks;
  double moved = 0.0, stayed = 0.0;
};

std::string checks_text(const std::vector<std::string>& checks) {
  std::string s = checks.front();
  if (checks.size() > 1) s += " and " + std::to_string(checks.size() - 1) + " more";
  return s;
}

}  // namespace

std::vector<int> check_rests_on(const StepSpec& spec, const CheckResult& check) {
  if (check.kind == "render") {
    for (const RenderCheck& r : spec.renders)
      if (r.name == check.name) return r.rests_on_steps;
    return {};
  }
  return spec.tests_rest_on_steps;
}

void charge_steps_at_fault(const PartSpec& spec, std::vector<StepResult>& steps) {
  // Which steps fail on their own checks, before anything is charged.
  std::map<int, size_t> index;
  std::vector<bool> failing(steps.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    index[steps[i].step] = i;
    failing[i] = steps[i].failed() > 0;
  }
  // Whether a step fails on a check that does not run step `k`: a later step is charged for a
  // check of step k only then. Otherwise a bug of step k that shows in the later step's checks
  // (a render that runs step k) would pass step k's own failures on to it.
  auto fails_apart_from = [&](size_t j, int k) {
    const StepSpec* st = spec.find_step(steps[j].step);
    for (const CheckResult& c : steps[j].checks) {
      if (c.skipped || c.pass) continue;
      if (!st) return true;
      const std::vector<int> rests = check_rests_on(*st, c);
      if (std::find(rests.begin(), rests.end(), k) == rests.end()) return true;
    }
    return false;
  };
  std::vector<std::map<size_t, Charge>> gave(steps.size()), took(steps.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    StepResult& k = steps[i];
    const StepSpec* st = spec.find_step(k.step);
    const int counted = k.counted();
    if (!st || counted == 0) continue;
    const double share = k.max_score / double(counted);
    for (const CheckResult& c : k.checks) {
      if (c.skipped || c.pass) continue;
      std::vector<int> rests = check_rests_on(*st, c);
      std::sort(rests.begin(), rests.end());
      size_t at_fault = steps.size();
      for (int j : rests) {
        auto it = index.find(j);
        if (j != k.step && it != index.end() && failing[it->second] &&
            (j < k.step || fails_apart_from(it->second, k.step))) {
          at_fault = it->second;
          break;
        }
      }
      if (at_fault == steps.size()) continue;  // the check's own step is at fault
      StepResult& j = steps[at_fault];
      const double moved = std::min(share, std::max(0.0, j.score));
      j.score -= moved;
      k.score += moved;
      Charge& g = gave[i][at_fault];
      g.other = at_fault;
      g.checks.push_back(c.name);
      g.moved += moved;
      g.stayed += share - moved;
      Charge& t = took[at_fault][i];
      t.other = i;
      t.checks.push_back(c.name);
      t.moved += moved;
    }
    if (k.score > k.max_score - 1e-9) k.score = k.max_score;  // rounding of the shares
  }
  for (size_t i = 0; i < steps.size(); ++i) {
    for (const auto& [j, g] : gave[i]) {
      steps[i].message += "\n" + checks_text(g.checks) + (g.checks.size() > 1 ? " run" : " runs") +
                          " step " + std::to_string(steps[j].step) + " (" + steps[j].name +
                          "), which fails: fix that step first. " + points_text(g.moved) +
                          " points are charged to it";
      if (g.stayed > 1e-9)
        steps[i].message += "; " + points_text(g.stayed) + " stay here, since step " +
                            std::to_string(steps[j].step) + " has no points left to lose";
      steps[i].message += ".";
    }
    for (const auto& [k, t] : took[i])
      steps[i].message += "\nCharged " + points_text(t.moved) + " points for " +
                          checks_text(t.checks) + " of step " + std::to_string(steps[k].step) +
                          " (" + steps[k].name + "), which " +
                          (t.checks.size() > 1 ? "run" : "runs") +
                          " this step's code and " + (t.checks.size() > 1 ? "fail" : "fails") +
                          " with it.";
  }
}

}  // namespace pt::grader
