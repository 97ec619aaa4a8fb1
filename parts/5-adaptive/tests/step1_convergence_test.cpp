// Part 5, step 1 (convergence): the stopping rule on hand-computed cases, and the running
// statistics it decides by.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "parts/5-adaptive/adaptive_sampling.h"

namespace pt {
namespace {

TEST(convergence, bright_pixel_variance_has_no_cancellation) {
  // Samples 1e6 + N(0, 0.1²): the float sums Σx, Σx² of the course lose the variance entirely
  // (Σx² ≈ 1e12·n has no digit left for 0.01·n). The running statistics keep it to 1%.
  std::mt19937_64 gen(11);
  std::normal_distribution<double> normal(0.0, 0.1);
  IlluminanceStats stats;
  std::vector<double> xs;
  for (int i = 0; i < 10000; ++i) {
    double x = 1e6 + normal(gen);
    xs.push_back(x);
    stats.add(x);
  }
  long double sum = 0;
  for (double x : xs) sum += x;
  long double mean = sum / xs.size(), ss = 0;
  for (double x : xs) ss += (x - mean) * (x - mean);
  double exact = double(ss / (xs.size() - 1));
  EXPECT_NEAR(stats.variance(), exact, 0.01 * exact);
  EXPECT_NEAR(stats.mean, double(mean), 1e-6);
}

TEST(convergence, rule_on_hand_computed_cases) {
  IlluminanceStats s;
  for (double x : {1.0, 3.0}) s.add(x);  // μ = 2, σ² = 2
  // Two estimate samples: I = 1.96·√(2/2) = 1.96 against tolerance·2.
  EXPECT_TRUE(pixel_converged(s, 2, 0.98f + 1e-6f));
  EXPECT_FALSE(pixel_converged(s, 2, 0.97f));
  // Eight estimate samples: the half-width is the estimate's, I = 1.96·√(2/8) = 0.98.
  EXPECT_TRUE(pixel_converged(s, 8, 0.49f + 1e-6f));
  EXPECT_FALSE(pixel_converged(s, 8, 0.48f));
  EXPECT_FALSE(pixel_converged(s, 0, 1000.0f)) << "no estimate sample, nothing to report";
  IlluminanceStats one;
  one.add(5.0);
  EXPECT_FALSE(pixel_converged(one, 10, 1.0f)) << "one sample says nothing about the variance";
}

}  // namespace
}  // namespace pt
