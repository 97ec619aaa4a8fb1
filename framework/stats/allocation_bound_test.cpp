// Not needed for the assignment.
// The allocation bound against cases worked by hand and against allocations tried one by one.
#include "framework/stats/allocation_bound.h"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace pt {
namespace {

RenderEstimate estimate_with(int w, int h, const std::vector<glm::vec3>& variance) {
  RenderEstimate e;
  e.width = w, e.height = h;
  e.mean.assign(variance.size(), glm::vec3(0.0f));
  e.variance = variance;
  e.count.assign(variance.size(), 16.0f);
  return e;
}

TEST(ConvergenceAllocationBound, EqualVarianceLeavesNothingToGain) {
  const Image ref(4, 3, glm::vec3(0.5f));
  const AllocationBound b = relmse_allocation_bound(estimate_with(4, 3, std::vector<glm::vec3>(12, glm::vec3(0.2f))), ref);
  EXPECT_NEAR(b.best_sample_fraction, 1.0, 1e-12);
  EXPECT_EQ(b.zero_variance_share, 0.0);
}

TEST(ConvergenceAllocationBound, PixelsWithoutVarianceAreTheSaving) {
  // A quarter of the pixels noisy, the rest exact (a sky, a light): the best allocation spends
  // nothing on the exact ones, so it needs a quarter of uniform's samples.
  std::vector<glm::vec3> var(16, glm::vec3(0.0f));
  for (int i = 0; i < 4; ++i) var[size_t(i)] = glm::vec3(0.3f);
  const AllocationBound b = relmse_allocation_bound(estimate_with(4, 4, var), Image(4, 4, glm::vec3(1.0f)));
  EXPECT_NEAR(b.best_sample_fraction, 0.25, 1e-12);
  EXPECT_NEAR(b.zero_variance_share, 0.75, 1e-12);
}

TEST(ConvergenceAllocationBound, CheapExactPixelsSaveLittleTime) {
  // Three quarters of the pixels exact but six times cheaper a sample than the noisy quarter
  // (a sky around a model): the samples saved are many, the time saved is not. Uniform spends
  // 0.75·1 + 0.25·6 = 2.25 a pixel-sample, the best allocation the noisy quarter's 0.25·6 = 1.5.
  std::vector<glm::vec3> var(16, glm::vec3(0.0f));
  std::vector<double> cost(16, 1.0);
  for (int i = 0; i < 4; ++i) var[size_t(i)] = glm::vec3(0.3f), cost[size_t(i)] = 6.0;
  const AllocationBound b =
      relmse_allocation_bound(estimate_with(4, 4, var), Image(4, 4, glm::vec3(1.0f)), cost);
  EXPECT_NEAR(b.best_sample_fraction, 0.25, 1e-12);
  EXPECT_NEAR(b.best_time_fraction, 1.5 / 2.25, 1e-12);
  // Without costs there is no time fraction to tell.
  EXPECT_TRUE(std::isnan(
      relmse_allocation_bound(estimate_with(4, 4, var), Image(4, 4, glm::vec3(1.0f))).best_time_fraction));
}

TEST(ConvergenceAllocationBound, WeighsEachPixelByItsReference) {
  // Same variance, references 3 and 0: a = 1/(9 + ε) and 1/ε, worked by hand.
  Image ref(2, 1, glm::vec3(0.0f));
  ref.at(0, 0) = glm::vec3(3.0f);
  const AllocationBound b =
      relmse_allocation_bound(estimate_with(2, 1, {glm::vec3(1.0f), glm::vec3(1.0f)}), ref);
  const double a0 = 1.0 / (9.0 + kRelMseEpsilon), a1 = 1.0 / kRelMseEpsilon;
  const double root = (std::sqrt(a0) + std::sqrt(a1)) / 2.0;
  EXPECT_NEAR(b.best_sample_fraction, root * root / ((a0 + a1) / 2.0), 1e-6);
}

/// relMSE's expected value for n_i samples per pixel: mean of a_i / n_i.
double expected_relmse(const std::vector<double>& a, const std::vector<double>& n) {
  double e = 0.0;
  for (size_t i = 0; i < a.size(); ++i) e += a[i] / n[i];
  return e / double(a.size());
}

TEST(ConvergenceAllocationBound, NoAllocationTriedBeatsIt) {
  // Random per-pixel variances; the bound's fraction f says: the best allocation of N samples
  // reaches uniform's error at N / f. Checked from first principles: n_i ∝ √a_i reaches exactly
  // that, and 2000 random reallocations of the same total never do better.
  std::mt19937_64 rng(17);
  std::lognormal_distribution<double> spread(0.0, 1.5);
  const int w = 8, h = 8, pixels = w * h;
  std::vector<glm::vec3> var(pixels);
  std::vector<double> a(pixels);
  Image ref(w, h);
  for (int i = 0; i < pixels; ++i) {
    var[size_t(i)] = glm::vec3(float(spread(rng)));
    ref.at(i % w, i / w) = glm::vec3(float(0.2 * spread(rng)));
    double ai = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double r = ref.at(i % w, i / w)[c];
      ai += double(var[size_t(i)][c]) / (r * r + kRelMseEpsilon);
    }
    a[size_t(i)] = ai / 3.0;
  }
  const double f = relmse_allocation_bound(estimate_with(w, h, var), ref).best_sample_fraction;
  ASSERT_GT(f, 0.0);
  ASSERT_LT(f, 1.0);

  const double total = 64.0 * pixels;
  double root_sum = 0.0;
  for (double ai : a) root_sum += std::sqrt(ai);
  std::vector<double> best(pixels);
  for (int i = 0; i < pixels; ++i) best[size_t(i)] = total * std::sqrt(a[size_t(i)]) / root_sum;
  const double best_error = expected_relmse(a, best);
  const std::vector<double> uniform_more(pixels, total / pixels / f);
  EXPECT_NEAR(best_error, expected_relmse(a, uniform_more), 1e-9 * best_error);

  std::uniform_real_distribution<double> wobble(0.5, 1.5);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> n(best);
    double sum = 0.0;
    for (double& ni : n) sum += (ni *= wobble(rng));
    for (double& ni : n) ni *= total / sum;
    EXPECT_GE(expected_relmse(a, n), best_error * (1.0 - 1e-12)) << "trial " << trial;
  }

  // The same with a cost per sample and a fixed time: n_i ∝ √(a_i / c_i) reaches uniform's error
  // in the time fraction the bound gives, and no reallocation of the same time does better.
  std::vector<double> cost(pixels);
  double cost_sum = 0.0;
  for (double& c : cost) cost_sum += (c = spread(rng));
  const double ft = relmse_allocation_bound(estimate_with(w, h, var), ref, cost).best_time_fraction;
  ASSERT_GT(ft, 0.0);
  ASSERT_LT(ft, 1.0);
  const double time = 64.0 * cost_sum;  // uniform's time at 64 samples a pixel
  double weight = 0.0;
  for (int i = 0; i < pixels; ++i) weight += std::sqrt(a[size_t(i)] * cost[size_t(i)]);
  std::vector<double> timed(pixels);
  for (int i = 0; i < pixels; ++i)
    timed[size_t(i)] = time * std::sqrt(a[size_t(i)] / cost[size_t(i)]) / weight;
  const double timed_error = expected_relmse(a, timed);
  EXPECT_NEAR(timed_error, expected_relmse(a, std::vector<double>(pixels, 64.0 / ft)),
              1e-9 * timed_error);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> n(timed);
    double spent = 0.0;
    for (int i = 0; i < pixels; ++i) spent += (n[size_t(i)] *= wobble(rng)) * cost[size_t(i)];
    for (double& ni : n) ni *= time / spent;
    EXPECT_GE(expected_relmse(a, n), timed_error * (1.0 - 1e-12)) << "trial " << trial;
  }
}

TEST(ConvergenceAllocationBound, RefusesMismatchedOrBrokenInput) {
  const Image ref(2, 2, glm::vec3(1.0f));
  EXPECT_THROW(relmse_allocation_bound(estimate_with(3, 1, std::vector<glm::vec3>(3, glm::vec3(1.0f))), ref),
               std::invalid_argument);
  std::vector<glm::vec3> var(4, glm::vec3(1.0f));
  var[3].y = -1.0f;
  try {
    relmse_allocation_bound(estimate_with(2, 2, var), ref);
    FAIL() << "a negative variance was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pixel (1, 1) channel 1"), std::string::npos) << e.what();
  }
  var[3].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(relmse_allocation_bound(estimate_with(2, 2, var), ref), std::invalid_argument);
  var[3].y = 1.0f;
  EXPECT_THROW(relmse_allocation_bound(estimate_with(2, 2, var), ref, {1.0, 1.0}),
               std::invalid_argument);  // a cost for every pixel, or none
  try {
    relmse_allocation_bound(estimate_with(2, 2, var), ref, {1.0, 0.0, 1.0, 1.0});
    FAIL() << "a cost of 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pixel (1, 0)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pt
