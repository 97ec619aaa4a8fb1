// Part 5: the stopping rule and the adaptive pixel loop, on sample streams whose mean and
// variance are known.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "5-adaptive/adaptive_sampling.h"

namespace pt {
namespace {

Camera test_camera() { return Camera{}; }

/// A radiance function that ignores the ray and plays back a stream of grey values.
struct Stream {
  std::vector<double> values;
  size_t next = 0;
  RadianceFn fn() {
    return [this](const Ray&, Rng&) {
      float v = float(values.at(next++));
      return glm::vec3(v);
    };
  }
};

/// The stopping rule computed independently: two-pass variance in long double.
bool reference_converged(const std::vector<double>& xs, size_t n, double tol) {
  if (n < 2) return false;
  long double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += xs[i];
  long double mean = sum / n, ss = 0;
  for (size_t i = 0; i < n; ++i) ss += (xs[i] - mean) * (xs[i] - mean);
  long double sigma = std::sqrt(ss / (n - 1));
  return 1.96L * sigma / std::sqrt((long double)n) <= tol * mean;
}

TEST(Part5Adaptive, StopsAtTheFirstBatchWhereTheRuleHolds) {
  // Gaussian samples, mean 1, σ 0.5, tolerance 0.05: the rule is met near
  // n* = (1.96·0.5 / 0.05)² ≈ 384 samples. Whatever the stream, the loop must stop at exactly
  // the first batch boundary where the rule (computed independently) holds, and not before.
  const int batch = 32, max_samples = 4096;
  const double tol = 0.05;
  std::vector<int> stops;
  for (int seed = 0; seed < 200; ++seed) {
    std::mt19937_64 gen(seed);
    std::normal_distribution<double> normal(1.0, 0.5);
    Stream s;
    for (int i = 0; i < max_samples; ++i) s.values.push_back(normal(gen));
    size_t expected = max_samples;
    for (size_t n = batch; n <= size_t(max_samples); n += batch)
      if (reference_converged(s.values, n, tol)) {
        expected = n;
        break;
      }
    Rng rng(seed);
    PixelStats stats;
    int taken = estimate_pixel_adaptive(test_camera(), PixelRef{0, 0, 1, 1},
                                        AdaptiveSettings{max_samples, batch, float(tol)}, rng,
                                        s.fn(), &stats);
    ASSERT_EQ(size_t(taken), expected) << "seed " << seed;
    ASSERT_EQ(stats.count, taken);
    stops.push_back(taken);
  }
  // The stopping points cluster around n* (σ and μ are estimated, so they scatter a little).
  double mean_stop = 0;
  for (int n : stops) mean_stop += n;
  mean_stop /= stops.size();
  EXPECT_GT(mean_stop, 384 * 0.8);
  EXPECT_LT(mean_stop, 384 * 1.25);
}

TEST(Part5Adaptive, NeverMoreThanTheMaximum) {
  // A stream far too noisy to converge: the loop stops at -s exactly.
  std::mt19937_64 gen(7);
  std::exponential_distribution<double> expo(1.0);
  Stream s;
  for (int i = 0; i < 100; ++i) s.values.push_back(expo(gen) * (i % 2 ? 100.0 : 0.001));
  Rng rng(1);
  PixelStats stats;
  int taken = estimate_pixel_adaptive(test_camera(), PixelRef{0, 0, 1, 1},
                                      AdaptiveSettings{50, 8, 0.001f}, rng, s.fn(), &stats);
  EXPECT_EQ(taken, 50);
  EXPECT_EQ(stats.count, 50);
}

TEST(Part5Adaptive, ConstantPixelStopsAfterOneBatch) {
  for (double v : {0.0, 0.25, 1.0, 1000.0}) {
    Stream s;
    s.values.assign(1000, v);
    Rng rng(3);
    PixelStats stats;
    int taken = estimate_pixel_adaptive(test_camera(), PixelRef{2, 3, 8, 8},
                                        AdaptiveSettings{512, 16, 0.05f}, rng, s.fn(), &stats);
    EXPECT_EQ(taken, 16) << "value " << v;
    EXPECT_DOUBLE_EQ(stats.mean.x, v);
  }
}

TEST(Part5Adaptive, BrightPixelVarianceHasNoCancellation) {
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

TEST(Part5Adaptive, RuleOnHandComputedCases) {
  IlluminanceStats s;
  for (double x : {1.0, 3.0}) s.add(x);  // μ = 2, σ² = 2, I = 1.96·√(2/2) = 1.96
  EXPECT_TRUE(pixel_converged(s, 0.98f + 1e-6f));
  EXPECT_FALSE(pixel_converged(s, 0.97f));
  IlluminanceStats one;
  one.add(5.0);
  EXPECT_FALSE(pixel_converged(one, 1.0f)) << "one sample says nothing about the variance";
}

}  // namespace
}  // namespace pt
