// Not needed for the assignment.
// A render's variance channels must be plausible against the reference's: the same estimator
// with other random numbers passes, a render whose variance (or sample count) was inflated to
// hide a bias fails.
#include "framework/stats/variance_consistency.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "framework/stats/block_ttest.h"

namespace pt {
namespace {

/// A 64×48 render of a smooth image whose samples are exponential (a heavy-ish tail, like
/// light transport) with mean m(x, y): per-sample variance m², estimated from `spp` samples.
RenderEstimate noisy_render(int spp, uint32_t seed, float scale = 1.0f) {
  RenderEstimate e;
  e.width = 64;
  e.height = 48;
  std::mt19937 rng(seed);
  for (int y = 0; y < e.height; ++y) {
    for (int x = 0; x < e.width; ++x) {
      float m = 0.2f + 0.6f * float(x) / e.width;
      std::exponential_distribution<double> d(1.0 / m);
      double sum = 0, sum2 = 0;
      for (int s = 0; s < spp; ++s) {
        double v = d(rng);
        sum += v;
        sum2 += v * v;
      }
      double mean = sum / spp, var = (sum2 - spp * mean * mean) / (spp - 1);
      e.mean.push_back(glm::vec3(float(mean) * scale));
      e.variance.push_back(glm::vec3(float(var) * scale * scale));
      e.count.push_back(float(spp));
    }
  }
  return e;
}

TEST(FrameworkVarianceConsistency, TheSameEstimatorWithOtherRandomNumbersPasses) {
  RenderEstimate reference = noisy_render(256, 1);
  for (uint32_t seed = 2; seed < 12; ++seed) {
    VarianceConsistencyOptions o;
    o.expected_count = 4;
    VarianceConsistencyResult r = check_variance_consistency(noisy_render(4, seed), reference, o);
    EXPECT_TRUE(r.pass) << "seed " << seed << ": " << r.summary;
    EXPECT_LT(r.image_ratio, 1.5);
  }
}

TEST(FrameworkVarianceConsistency, TwiceTooBrightWithInflatedVarianceFails) {
  // The attack: a biased render that states a huge variance passes the block t-test alone.
  RenderEstimate reference = noisy_render(256, 1);
  RenderEstimate cheat = noisy_render(4, 5, 2.0f);
  for (glm::vec3& v : cheat.variance) v *= 1e6f;
  EXPECT_TRUE(block_t_test(cheat, reference).pass) << "the t-test alone is fooled";
  VarianceConsistencyResult r = check_variance_consistency(cheat, reference);
  EXPECT_FALSE(r.pass);
  EXPECT_GT(r.image_ratio, 1e5);
  EXPECT_NE(r.summary.find("not plausible"), std::string::npos) << r.summary;
}

TEST(FrameworkVarianceConsistency, AnUnderstatedSampleCountFails) {
  RenderEstimate reference = noisy_render(256, 1);
  RenderEstimate cheat = noisy_render(4, 6);
  for (float& c : cheat.count) c = 1.0f;
  VarianceConsistencyOptions o;
  o.expected_count = 4;
  VarianceConsistencyResult r = check_variance_consistency(cheat, reference, o);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.summary.find("asked for 4"), std::string::npos) << r.summary;
  // An adaptive render may stop early, never late.
  o.adaptive = true;
  EXPECT_TRUE(check_variance_consistency(cheat, reference, o).pass);
  for (float& c : cheat.count) c = 5.0f;
  EXPECT_FALSE(check_variance_consistency(cheat, reference, o).pass);
}

TEST(FrameworkVarianceConsistency, NonFiniteOrNegativeVarianceFails) {
  RenderEstimate reference = noisy_render(64, 1);
  RenderEstimate bad = noisy_render(4, 2);
  bad.variance[100].y = NAN;
  EXPECT_FALSE(check_variance_consistency(bad, reference).pass);
  bad.variance[100].y = -1.0f;
  EXPECT_FALSE(check_variance_consistency(bad, reference).pass);
}

TEST(FrameworkVarianceConsistency, ZeroVarianceBlocksAllowOnlyAFloor) {
  RenderEstimate reference = noisy_render(64, 1), render = noisy_render(4, 2);
  for (glm::vec3& v : reference.variance) v = glm::vec3(0.0f);
  for (glm::vec3& v : render.variance) v = glm::vec3(0.0f);
  EXPECT_TRUE(check_variance_consistency(render, reference).pass);
  for (glm::vec3& v : render.variance) v = glm::vec3(1.0f);
  EXPECT_FALSE(check_variance_consistency(render, reference).pass);
}

}  // namespace
}  // namespace pt
