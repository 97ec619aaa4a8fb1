// Part 5, step 1 (convergence): the stopping rule's hand-computed cases, shaped as a stopping rule
// hands them over (split: decision and estimate samples apart; course: the same samples, so the
// two counts are equal), and the mistakes whose answers a wrong rule gives.
// step1_convergence_test.cpp grades them under the assignment's rule;
// step1_convergence_stress_test.cpp runs them under the other one.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "parts/5-adaptive/adaptive_sampling.h"

namespace pt::test::convergence {

struct Case {
  IlluminanceStats decision;
  long estimate_count;
  float tolerance;
  bool converged;  ///< the right answer
  const char* why;
};

inline IlluminanceStats stats_of(std::initializer_list<double> xs) {
  IlluminanceStats s;
  for (double x : xs) s.add(x);
  return s;
}

/// Mistakes students make, each as the rule it computes (σ², μ from the decision samples).
struct Mistake {
  const char* cause;
  std::function<bool(const IlluminanceStats&, long, float)> rule;
};

inline bool half_width_rule(const IlluminanceStats& d, long n, float tol,
                            const std::function<double(double var, double n, double nd)>& half_width) {
  if (d.count < 2 || n < 1) return false;
  return half_width(d.variance(), double(n), double(d.count)) <= double(tol) * d.mean;
}

/// The mistakes whose answers differ from the right ones under `rule`.
inline std::vector<Mistake> mistakes(StoppingRule rule) {
  const Mistake variance_as_std{
      "the variance used as the standard deviation (σ is the square root of decision.variance())?",
      [](const IlluminanceStats& d, long n, float t) {
        return half_width_rule(d, n, t, [](double v, double m, double) { return 1.96 * v / std::sqrt(m); });
      }};
  const Mistake decision_in_count{
      rule == StoppingRule::course
          ? "the samples counted twice? (n = estimate_count: under the course's rule the decision "
            "samples are the estimate's own)"
          : "the decision samples counted in n_E? (the half-width is the reported estimate's: n_E "
            "= estimate_count alone)",
      [](const IlluminanceStats& d, long n, float t) {
        return half_width_rule(d, n, t, [](double v, double m, double nd) { return 1.96 * std::sqrt(v / (m + nd)); });
      }};
  const Mistake decision_count_under_root{
      "the decision count under the root? (the half-width is the estimate's: √estimate_count)",
      [](const IlluminanceStats& d, long n, float t) {
        return half_width_rule(d, n, t, [](double v, double, double nd) { return 1.96 * std::sqrt(v / nd); });
      }};
  const Mistake over_n{"σ divided by n_E, not by √n_E?",
                              [](const IlluminanceStats& d, long n, float t) {
                                return half_width_rule(d, n, t, [](double v, double m, double) {
                                  return 1.96 * std::sqrt(v) / m;
                                });
                              }};
  const Mistake no_196{"the factor 1.96 of a 95% interval left out?",
                              [](const IlluminanceStats& d, long n, float t) {
                                return half_width_rule(d, n, t, [](double v, double m, double) {
                                  return std::sqrt(v / m);
                                });
                              }};
  // Near misses, each a rule a reading of the page could give: the cases below tell every one
  // from every other, so a hint names one only when its answers are that mistake's alone.
  const Mistake population_variance{
      "the variance divided by the count, not by the count - 1? (decision.variance() is the "
      "sample variance already)",
      [](const IlluminanceStats& d, long n, float t) {
        return half_width_rule(d, n, t, [](double v, double m, double nd) {
          return 1.96 * std::sqrt(v * (nd - 1.0) / nd / m);
        });
      }};
  const Mistake z_90{"1.645 (a 90% interval) in place of 1.96 (95%)?",
                     [](const IlluminanceStats& d, long n, float t) {
                       return half_width_rule(d, n, t, [](double v, double m, double) {
                         return 1.645 * std::sqrt(v / m);
                       });
                     }};
  const Mistake absolute_tolerance{
      "the half-width compared with the tolerance itself, not with tolerance·μ?",
      [](const IlluminanceStats& d, long n, float t) {
        if (d.count < 2 || n < 1) return false;
        return 1.96 * std::sqrt(d.variance() / double(n)) <= double(t);
      }};
  // Under the course's rule the two counts are the same number, so either under the root is right.
  if (rule == StoppingRule::course)
    return {variance_as_std, decision_in_count, over_n, no_196, population_variance, z_90,
            absolute_tolerance};
  return {variance_as_std, decision_in_count, decision_count_under_root, over_n, no_196,
          population_variance, z_90, absolute_tolerance};
}

/// The cases the split rule hands over: decision samples apart from the estimate's.
inline std::vector<Case> split_rule_cases() {
  const IlluminanceStats s = stats_of({1.0, 3.0});      // μ = 2, σ² = 2
  const IlluminanceStats w = stats_of({2.0, 4.0, 6.0});  // μ = 4, σ² = 4
  const IlluminanceStats b = stats_of({9.0, 11.0});      // μ = 10, σ² = 2
  return {
      {s, 2, 0.98f + 1e-6f, true, "μ 2, σ² 2, 2 estimate samples: I = 1.96·√(2/2) = 1.96 ≤ 0.98·2"},
      {s, 2, 0.97f, false, "μ 2, σ² 2, 2 estimate samples: I = 1.96 > 0.97·2"},
      {s, 8, 0.49f + 1e-6f, true, "μ 2, σ² 2, 8 estimate samples: I = 1.96·√(2/8) = 0.98 ≤ 0.49·2"},
      {s, 8, 0.48f, false, "μ 2, σ² 2, 8 estimate samples: I = 0.98 > 0.48·2"},
      {s, 8, 0.46f, false, "μ 2, σ² 2, 8 estimate samples: I = 0.98 > 0.46·2"},
      {s, 8, 0.3f, false, "μ 2, σ² 2, 8 estimate samples: I = 0.98 > 0.3·2"},
      {s, 8, 0.2f, false, "μ 2, σ² 2, 8 estimate samples: I = 0.98 > 0.2·2"},
      {w, 16, 0.245f + 1e-6f, true, "μ 4, σ² 4, 16 estimate samples: I = 1.96·2/4 = 0.98 ≤ 0.245·4"},
      {w, 16, 0.24f, false, "μ 4, σ² 4, 16 estimate samples: I = 0.98 > 0.24·4"},
      {w, 3, 0.566f, true, "μ 4, σ² 4, 3 estimate samples: I = 1.96·2/√3 = 2.263 ≤ 0.566·4"},
      {w, 3, 0.5f, false, "μ 4, σ² 4, 3 estimate samples: I = 2.263 > 0.5·4"},
      {stats_of({0.0, 0.0, 0.0}), 9, 0.05f, true, "a black pixel, σ = 0: I = 0 ≤ 0.05·0, converged"},
      {stats_of({0.25, 0.25}), 6, 0.01f, true, "σ = 0: I = 0 ≤ 0.01·0.25, converged"},
      {s, 0, 1000.0f, false, "no estimate sample: nothing to report, not converged"},
      {stats_of({5.0}), 10, 1.0f, false, "one decision sample says nothing about σ: not converged"},
      // Between the near misses' half-widths (σ² with n: 0.80; 1.645: 0.82; n_E + 3: 0.90).
      {w, 16, 0.2025f, false, "μ 4, σ² 4, 16 estimate samples: I = 0.98 > 0.2025·4 = 0.81"},
      {w, 16, 0.2125f, false, "μ 4, σ² 4, 16 estimate samples: I = 0.98 > 0.2125·4 = 0.85"},
      // A bright pixel: tolerance·μ is not the tolerance.
      {b, 8, 0.15f, true, "μ 10, σ² 2, 8 estimate samples: I = 1.96·√(2/8) = 0.98 ≤ 0.15·10"},
  };
}

/// The cases the course's rule hands over: every sample both decides and counts, so
/// estimate_count is the decision statistics' own count.
inline std::vector<Case> course_rule_cases() {
  const IlluminanceStats s = stats_of({1.0, 3.0});                  // μ 2, σ² 2
  const IlluminanceStats w = stats_of({2.0, 4.0, 6.0});             // μ 4, σ² 4
  const IlluminanceStats e = stats_of({1, 1, 1, 1, 3, 3, 3, 3});    // μ 2, σ² 8/7
  const IlluminanceStats b = stats_of({9.0, 11.0});                 // μ 10, σ² 2
  return {
      {s, 2, 0.98f + 1e-6f, true, "μ 2, σ² 2, 2 samples: I = 1.96·√(2/2) = 1.96 ≤ 0.98·2"},
      {s, 2, 0.97f, false, "μ 2, σ² 2, 2 samples: I = 1.96 > 0.97·2"},
      {s, 2, 0.6f, false, "μ 2, σ² 2, 2 samples: I = 1.96 > 0.6·2"},
      {w, 3, 0.566f, true, "μ 4, σ² 4, 3 samples: I = 1.96·2/√3 = 2.263 ≤ 0.566·4"},
      {w, 3, 0.5f, false, "μ 4, σ² 4, 3 samples: I = 2.263 > 0.5·4"},
      {e, 8, 0.3705f, true, "μ 2, σ² 8/7, 8 samples: I = 1.96·√(1/7) = 0.7408 ≤ 0.3705·2"},
      {e, 8, 0.37f, false, "μ 2, σ² 8/7, 8 samples: I = 0.7408 > 0.37·2"},
      {e, 8, 0.25f, false, "μ 2, σ² 8/7, 8 samples: I = 0.7408 > 0.25·2"},
      {stats_of({0.0, 0.0, 0.0}), 3, 0.05f, true, "a black pixel, σ = 0: I = 0 ≤ 0.05·0, converged"},
      {stats_of({0.25, 0.25}), 2, 0.01f, true, "σ = 0: I = 0 ≤ 0.01·0.25, converged"},
      {IlluminanceStats(), 0, 1000.0f, false, "no sample: nothing to report, not converged"},
      {stats_of({5.0}), 1, 1.0f, false, "one sample says nothing about σ: not converged"},
      // Between the near misses' half-widths (σ² with n: 0.693; 1.645: 0.622; n counted twice:
      // 0.524).
      {e, 8, 0.325f, false, "μ 2, σ² 8/7, 8 samples: I = 0.7408 > 0.325·2 = 0.65"},
      {e, 8, 0.3f, false, "μ 2, σ² 8/7, 8 samples: I = 0.7408 > 0.3·2 = 0.6"},
      // A bright pixel: tolerance·μ is not the tolerance.
      {b, 2, 0.3f, true, "μ 10, σ² 2, 2 samples: I = 1.96·√(2/2) = 1.96 ≤ 0.3·10"},
  };
}

/// pixel_converged on the hand-computed cases `rule` hands over; a failure names the mistake
/// whose answers are exactly the ones it got, if one is.
inline void rule_on_hand_computed_cases(StoppingRule rule) {
  const std::vector<Case> cases =
      rule == StoppingRule::course ? course_rule_cases() : split_rule_cases();
  std::vector<bool> got;
  std::ostringstream wrong;
  for (const Case& c : cases) {
    got.push_back(pixel_converged(c.decision, c.estimate_count, c.tolerance));
    if (got.back() != c.converged)
      wrong << "\n  " << c.why << ": expected " << (c.converged ? "converged" : "not converged")
            << ", got " << (got.back() ? "converged" : "not converged");
  }
  if (wrong.str().empty()) return;
  const bool all_same = std::all_of(got.begin(), got.end(), [&](bool g) { return g == got[0]; });
  std::vector<const char*> fits;
  for (const Mistake& m : all_same ? std::vector<Mistake>() : mistakes(rule)) {
    bool same = true;
    for (size_t i = 0; i < cases.size() && same; ++i)
      same = m.rule(cases[i].decision, cases[i].estimate_count, cases[i].tolerance) == got[i];
    if (same) fits.push_back(m.cause);
  }
  std::string cause;
  if (fits.size() == 1) cause = std::string("\nEvery answer is what this mistake gives: ") + fits[0];
  for (size_t i = 0; fits.size() > 1 && i < fits.size(); ++i)
    cause += std::string(i == 0 ? "\nEvery answer is what each of these mistakes gives: " : "; or ") + fits[i];
  if (all_same)
    cause = std::string("\nThe answer is always \"") + (got[0] ? "converged" : "not converged") +
            "\", whatever the samples say: is the rule written yet?";
  ADD_FAILURE() << "pixel_converged is wrong on hand-computed cases:" << wrong.str() << cause;
}

}  // namespace pt::test::convergence
