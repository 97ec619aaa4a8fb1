// Not needed for the assignment.
// The running statistics of a pixel's illuminances keep the variance of a bright pixel whose
// samples barely differ.
#include "framework/stats/illuminance_stats.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace pt {
namespace {

TEST(FrameworkIlluminanceStats, BrightPixelVarianceHasNoCancellation) {
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

}  // namespace
}  // namespace pt
