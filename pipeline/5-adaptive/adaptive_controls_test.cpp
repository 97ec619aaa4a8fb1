// Not needed for the assignment.
// The controls of Part 5's unbiasedness test: two biased stopping rules on the same heavy-tailed
// pixel, which the same block t-test at the same significance must catch, or it has no power
// there. They run no student code (a stub must not score on them), so they are not Part 5's.
// SOLUTION-ONLY FILE: not in the student handout, since its controls write out Part 5's loop
// under the course's rule and the convergence test (answers to both steps).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "framework/stats/block_ttest.h"
#include "parts/5-adaptive/tests/heavy_tailed_pixel.h"

namespace pt {
namespace {

/// The course's rule, here only as a control: it decides on the very samples it averages.
int biased_course_rule(const AdaptiveSettings& settings, Rng& rng, PixelStats* stats) {
  IlluminanceStats lum;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < settings.batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec3 L = test::heavy_tailed_sample(rng);
      stats->add(L);
      lum.add(illuminance(L));
    }
    if (lum.count > 1 && 1.96 * std::sqrt(lum.variance() / double(lum.count)) <=
                             double(settings.tolerance) * lum.mean)
      break;
  }
  return taken;
}

/// A subtler mistake, also only a control: the decision samples are chosen apart, as the rule
/// says, but averaged into the value too, so the value still depends on when it stopped.
int decision_samples_also_averaged(const AdaptiveSettings& settings, Rng& rng,
                                   PixelStats* stats) {
  IlluminanceStats decision;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < settings.batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec3 L = test::heavy_tailed_sample(rng);
      stats->add(L);
      if (taken % 4 == 3) decision.add(illuminance(L));
    }
    // The solution's rule, written out so the control does not depend on the student's code.
    if (decision.count > 1 && 1.96 * std::sqrt(decision.variance() / double(stats->count)) <=
                                  double(settings.tolerance) * decision.mean)
      break;
  }
  return taken;
}

TEST(PipelineAdaptiveControls, CourseRuleOnTheSameSamplesIsCaught) {
  // Same stream, same settings, same test at the same significance, but the stopping decision
  // made on the samples that are averaged: the block t-test must fail, or it has no power here.
  Film film(test::kUnbiasW, test::kUnbiasH);
  for (int y = 0; y < test::kUnbiasH; ++y)
    for (int x = 0; x < test::kUnbiasW; ++x) {
      Rng rng(42, uint64_t(y) * test::kUnbiasW + x);
      biased_course_rule(test::kUnbiasSettings, rng, &film.at(x, y));
    }
  BlockTestResult r =
      block_t_test(film.estimate(), test::non_adaptive_reference(), {test::kUnbiasBlock, 0.01});
  std::cout << "course rule: " << r.summary << "\n";
  EXPECT_FALSE(r.pass) << "the course's rule went undetected: " << r.summary;
  EXPECT_LT(r.overall_ratio.x, 0.97f) << r.summary;
}

TEST(PipelineAdaptiveControls, DecisionSamplesAlsoAveragedIsCaught) {
  // The stopping rule of the solution, but the decision samples also enter the value: the same
  // test at the same significance must catch it (a bias near 6%, smaller than the course's).
  Film film(test::kUnbiasW, test::kUnbiasH);
  for (int y = 0; y < test::kUnbiasH; ++y)
    for (int x = 0; x < test::kUnbiasW; ++x) {
      Rng rng(42, uint64_t(y) * test::kUnbiasW + x);
      decision_samples_also_averaged(test::kUnbiasSettings, rng, &film.at(x, y));
    }
  BlockTestResult r =
      block_t_test(film.estimate(), test::non_adaptive_reference(), {test::kUnbiasBlock, 0.01});
  std::cout << "decision samples averaged too: " << r.summary << "\n";
  EXPECT_FALSE(r.pass) << "averaging the decision samples went undetected: " << r.summary;
}

}  // namespace
}  // namespace pt
