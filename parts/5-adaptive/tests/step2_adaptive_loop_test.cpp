// Part 5: the stopping rule and the adaptive pixel loop, on sample streams whose mean and
// variance are known; the sample-rate image; and that the adaptive estimate is unbiased.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parts/5-adaptive/adaptive_sampling.h"
#include "framework/render/sample_rate.h"
#include "framework/render/film.h"
#include "framework/render/tile_renderer.h"
#include "framework/stats/block_ttest.h"

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

/// The first n samples of a stream split as the rule splits them, computed independently:
/// every fourth sample (indices 3, 7, ...) decides, the others are the estimate.
struct Split {
  std::vector<long double> decision, estimate;
};
Split split_stream(const std::vector<double>& xs, size_t n) {
  Split s;
  for (size_t i = 0; i < n; ++i) (i % 4 == 3 ? s.decision : s.estimate).push_back(float(xs[i]));
  return s;
}

long double mean_of(const std::vector<long double>& xs) {
  long double sum = 0;
  for (long double x : xs) sum += x;
  return sum / xs.size();
}

/// The stopping rule computed independently: two-pass variance of the decision samples in long
/// double, the half-width of the estimate's mean.
bool reference_converged(const std::vector<double>& xs, size_t n, double tol) {
  Split s = split_stream(xs, n);
  if (s.decision.size() < 2 || s.estimate.empty()) return false;
  long double mean = mean_of(s.decision), ss = 0;
  for (long double x : s.decision) ss += (x - mean) * (x - mean);
  long double sigma = std::sqrt(ss / (s.decision.size() - 1));
  return 1.96L * sigma / std::sqrt((long double)s.estimate.size()) <= tol * mean;
}

TEST(Part5Adaptive, StopsAtTheFirstBatchWhereTheRuleHolds) {
  // Gaussian samples, mean 1, σ 0.5, tolerance 0.05: the rule is met near
  // n_E* = (1.96·0.5 / 0.05)² ≈ 384 estimate samples, i.e. 512 samples taken. Whatever the
  // stream, the loop must stop at exactly the first batch boundary where the rule (computed
  // independently) holds, and not before; the estimate holds exactly the non-decision samples.
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
    Split split = split_stream(s.values, expected);
    ASSERT_EQ(size_t(stats.count), split.estimate.size()) << "seed " << seed;
    ASSERT_EQ(size_t(stats.decision_samples), split.decision.size()) << "seed " << seed;
    ASSERT_EQ(stats.samples_taken(), taken);
    ASSERT_NEAR(stats.mean.x, double(mean_of(split.estimate)), 1e-9)
        << "the value must be the mean of the estimate samples only, seed " << seed;
    stops.push_back(taken);
  }
  // The stopping points cluster around 512 (σ and μ are estimated, so they scatter a little).
  double mean_stop = 0;
  for (int n : stops) mean_stop += n;
  mean_stop /= stops.size();
  EXPECT_GT(mean_stop, 512 * 0.8);
  EXPECT_LT(mean_stop, 512 * 1.25);
}

TEST(Part5Adaptive, NeverMoreThanTheMaximum) {
  // A stream far too noisy to converge: the loop stops at -s exactly, 12 of the 50 samples
  // (indices 3, 7, ..., 47) having gone to the decision.
  std::mt19937_64 gen(7);
  std::exponential_distribution<double> expo(1.0);
  Stream s;
  for (int i = 0; i < 100; ++i) s.values.push_back(expo(gen) * (i % 2 ? 100.0 : 0.001));
  Rng rng(1);
  PixelStats stats;
  int taken = estimate_pixel_adaptive(test_camera(), PixelRef{0, 0, 1, 1},
                                      AdaptiveSettings{50, 8, 0.001f}, rng, s.fn(), &stats);
  EXPECT_EQ(taken, 50);
  EXPECT_EQ(stats.count, 38);
  EXPECT_EQ(stats.samples_taken(), 50);
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
    EXPECT_EQ(stats.count, 12) << "value " << v;
    EXPECT_DOUBLE_EQ(stats.mean.x, v);
  }
}

/// Renders a w × h film through the tile renderer with Part 5's loop, as the pathtracer does,
/// and returns the samples each pixel's call said it took.
std::vector<int> render_adaptive(const RadianceFn& radiance, const AdaptiveSettings& adaptive,
                                 uint64_t seed, Film* film, RenderReport* report) {
  RenderSettings settings;
  settings.width = film->width();
  settings.height = film->height();
  settings.samples_per_pixel = adaptive.max_samples;
  settings.threads = 1;
  settings.seed = seed;
  std::vector<int> taken(size_t(film->width()) * size_t(film->height()), -1);
  Camera camera = test_camera();
  PixelFn pixel = [&](int x, int y, Rng& rng, TraceContext&, PixelStats* stats) {
    taken[size_t(y) * size_t(film->width()) + size_t(x)] = estimate_pixel_adaptive(
        camera, PixelRef{x, y, film->width(), film->height()}, adaptive, rng, radiance, stats);
  };
  *report = render_tiles(settings, pixel, film);
  return taken;
}

TEST(Part5Adaptive, ConstantSceneStopsEveryPixelAfterTheFirstBatch) {
  Film film(24, 18);
  RenderReport report;
  const AdaptiveSettings adaptive{256, 32, 0.05f};
  std::vector<int> taken = render_adaptive(
      [](const Ray&, Rng&) { return glm::vec3(0.3f, 0.6f, 0.9f); }, adaptive, 5, &film, &report);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      ASSERT_EQ(taken[size_t(y) * 24 + size_t(x)], 32) << x << "," << y;
      ASSERT_EQ(film.at(x, y).count, 24) << x << "," << y;
      ASSERT_EQ(film.at(x, y).mean, glm::dvec3(glm::vec3(0.3f, 0.6f, 0.9f)));
    }
  EXPECT_EQ(report.samples, 24L * 18 * 32);
}

TEST(Part5Adaptive, SampleRateImageShowsTheSamplesTaken) {
  // Noise that grows across the image, so pixels stop at different batches; the rate image must
  // show every sample each pixel took (decision samples included), the EXR's count channel only
  // the samples its mean averages.
  Film film(16, 8);
  RenderReport report;
  const AdaptiveSettings adaptive{512, 16, 0.05f};
  RadianceFn noisy = [](const Ray& ray, Rng& rng) {
    float spread = 0.05f + 1.5f * std::clamp(ray.d.x + 0.5f, 0.0f, 1.0f);
    return glm::vec3(1.0f + spread * (rng.next_float() - 0.5f));
  };
  std::vector<int> taken = render_adaptive(noisy, adaptive, 9, &film, &report);
  Image rate = sample_rate_image(film, adaptive.max_samples);
  RenderEstimate estimate = film.estimate();
  long total = 0;
  int least = adaptive.max_samples, most = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      size_t i = size_t(y) * 16 + size_t(x);
      EXPECT_EQ(rate.at(x, y), sample_rate_colour(float(taken[i]) / 512.0f)) << x << "," << y;
      EXPECT_EQ(estimate.count[i], float(taken[i] - taken[i] / 4)) << x << "," << y;
      total += taken[i];
      least = std::min(least, taken[i]);
      most = std::max(most, taken[i]);
    }
  EXPECT_LT(least, most) << "the scene is meant to make pixels stop at different batches";
  EXPECT_EQ(report.samples, total);
  EXPECT_EQ(film.total_samples(), total);
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

// --- Unbiasedness -----------------------------------------------------------------------------

/// A heavy-tailed pixel: a dim background most of the time, a rare bright firefly (p = 0.05,
/// mean 0.3 in all). A batch that misses every firefly has zero spread and looks converged.
glm::vec3 heavy_tailed_sample(Rng& rng) {
  return glm::vec3(rng.next_float() < 0.05f ? 2.2f : 0.2f);
}

/// The course's rule, here only as a control: it decides on the very samples it averages.
int biased_course_rule(const AdaptiveSettings& settings, Rng& rng, PixelStats* stats) {
  IlluminanceStats lum;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < settings.batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec3 L = heavy_tailed_sample(rng);
      stats->add(L);
      lum.add(illuminance(L));
    }
    if (lum.count > 1 && 1.96 * std::sqrt(lum.variance() / double(lum.count)) <=
                             double(settings.tolerance) * lum.mean)
      break;
  }
  return taken;
}

// 128 × 128 pixels in 32-pixel blocks: each block mean has a standard error near 1% of the
// mean, so a bias of about 4% in a block is caught at the Bonferroni threshold.
/// A subtler mistake, also only a control: the decision samples are chosen apart, as the rule
/// says, but averaged into the value too, so the value still depends on when it stopped.
int decision_samples_also_averaged(const AdaptiveSettings& settings, Rng& rng,
                                   PixelStats* stats) {
  IlluminanceStats decision;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < settings.batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec3 L = heavy_tailed_sample(rng);
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

constexpr int kUnbiasW = 128, kUnbiasH = 128, kUnbiasBlock = 32, kReferenceSamples = 256;
constexpr AdaptiveSettings kUnbiasSettings{256, 32, 0.05f};

/// Non-adaptive: every pixel takes kReferenceSamples samples, on random numbers of its own.
RenderEstimate non_adaptive_reference() {
  Film film(kUnbiasW, kUnbiasH);
  for (int y = 0; y < kUnbiasH; ++y)
    for (int x = 0; x < kUnbiasW; ++x) {
      Rng rng(1000003, uint64_t(y) * kUnbiasW + x);
      for (int i = 0; i < kReferenceSamples; ++i) film.at(x, y).add(heavy_tailed_sample(rng));
    }
  return film.estimate();
}

TEST(Part5AdaptiveUnbiased, HeavyTailedImageMatchesTheNonAdaptiveOne) {
  // The block t-test of the grader (family-wise significance 0.01): an
  // unbiased adaptive estimate fails it with probability at most 1% (fixed seeds, so this test
  // is deterministic; on seeds 100-199 it passed 100 times of 100, and the second control was
  // caught 100 times of 100). The controls below show the same test catches a bias here.
  Film film(kUnbiasW, kUnbiasH);
  RenderReport report;
  render_adaptive([](const Ray&, Rng& rng) { return heavy_tailed_sample(rng); }, kUnbiasSettings,
                  42, &film, &report);
  long stopped_early = 0;
  for (int y = 0; y < kUnbiasH; ++y)
    for (int x = 0; x < kUnbiasW; ++x)
      stopped_early += film.at(x, y).samples_taken() < kUnbiasSettings.max_samples;
  ASSERT_GT(stopped_early, kUnbiasW * kUnbiasH / 4)
      << "the stream must make many pixels stop early, or the test says nothing";
  BlockTestResult r = block_t_test(film.estimate(), non_adaptive_reference(), {kUnbiasBlock, 0.01});
  EXPECT_TRUE(r.pass) << r.summary;
  std::cout << "adaptive: " << r.summary << "\n";
}

TEST(Part5AdaptiveUnbiased, ControlCourseRuleOnTheSameSamplesIsCaught) {
  // Same stream, same settings, same test at the same significance, but the stopping decision
  // made on the samples that are averaged: the block t-test must fail, or it has no power here.
  Film film(kUnbiasW, kUnbiasH);
  for (int y = 0; y < kUnbiasH; ++y)
    for (int x = 0; x < kUnbiasW; ++x) {
      Rng rng(42, uint64_t(y) * kUnbiasW + x);
      biased_course_rule(kUnbiasSettings, rng, &film.at(x, y));
    }
  BlockTestResult r = block_t_test(film.estimate(), non_adaptive_reference(), {kUnbiasBlock, 0.01});
  std::cout << "course rule: " << r.summary << "\n";
  EXPECT_FALSE(r.pass) << "the course's rule went undetected: " << r.summary;
  EXPECT_LT(r.overall_ratio.x, 0.97f) << r.summary;
}

TEST(Part5AdaptiveUnbiased, ControlDecisionSamplesAlsoAveragedIsCaught) {
  // The stopping rule of the solution, but the decision samples also enter the value: the same
  // test at the same significance must catch it (a bias near 6%, smaller than the course's).
  Film film(kUnbiasW, kUnbiasH);
  for (int y = 0; y < kUnbiasH; ++y)
    for (int x = 0; x < kUnbiasW; ++x) {
      Rng rng(42, uint64_t(y) * kUnbiasW + x);
      decision_samples_also_averaged(kUnbiasSettings, rng, &film.at(x, y));
    }
  BlockTestResult r = block_t_test(film.estimate(), non_adaptive_reference(), {kUnbiasBlock, 0.01});
  std::cout << "decision samples averaged too: " << r.summary << "\n";
  EXPECT_FALSE(r.pass) << "averaging the decision samples went undetected: " << r.summary;
}

}  // namespace
}  // namespace pt
