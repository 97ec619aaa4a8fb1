// Not needed for the assignment.
// The block t-test on synthetic renders whose truth is known: the same truth with other random
// numbers passes at the stated rate, a biased one fails, broken input fails.
#include "framework/stats/block_ttest.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "framework/render/pixel_stats.h"
#include "framework/sampling/rng.h"

namespace pt {
namespace {

constexpr int kWidth = 64, kHeight = 48;

/// The true image: a black band on the left (no noise at all there, as a background), a
/// coloured ramp elsewhere.
glm::vec3 truth(int x, int y) {
  if (x < 16) return glm::vec3(0.0f);
  float u = float(x) / kWidth, v = float(y) / kHeight;
  return {0.2f + 0.6f * u, 0.5f, 0.3f + 0.4f * v};
}

/// A render of the truth times `scale` with `samples` samples per pixel, each sample uniform on
/// [0, 2·value] per channel (a noisy, non-Gaussian estimator whose mean is the value).
RenderEstimate synthetic(int samples, uint64_t seed, float scale = 1.0f) {
  RenderEstimate e;
  e.width = kWidth;
  e.height = kHeight;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      Rng rng(seed, uint64_t(y) * kWidth + x);
      glm::vec3 value = truth(x, y) * scale;
      PixelStats stats;
      for (int s = 0; s < samples; ++s) {
        stats.add(2.0f * value * glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()));
      }
      e.mean.push_back(glm::vec3(stats.mean));
      e.variance.push_back(glm::vec3(stats.variance()));
      e.count.push_back(float(stats.count));
    }
  }
  return e;
}

TEST(FrameworkBlockTest, SameTruthOtherSeedsPassAtTheStatedRate) {
  // Bonferroni at α/36 (12 blocks × 3 channels), with 9 noisy blocks × 3 independent channels
  // (the black band cannot differ), makes the false alarm rate 1 − (1 − α/36)^27 ≈ 0.037 for
  // α = 0.05: about 37 of 1000 seeds (standard deviation 6); 10000 seeds gave 3.1%, a little
  // under, as Bonferroni is. Seeds are fixed, so the count is too; the bounds are where a
  // correct test lands with probability > 0.999.
  BlockTestOptions options;
  options.alpha = 0.05;
  int failures = 0;
  const int trials = 1000;
  for (int trial = 0; trial < trials; ++trial) {
    // A new reference each time too: with one fixed reference the trials share its noise and the
    // rate drifts from α by chance.
    BlockTestResult r =
        block_t_test(synthetic(8, 2000 + trial), synthetic(32, 100000 + trial), options);
    EXPECT_EQ(r.blocks, 12);
    EXPECT_FALSE(r.nonfinite);
    if (!r.pass) ++failures;
  }
  EXPECT_GE(failures, 18) << "the test fires too rarely: its p-values are too large";
  EXPECT_LE(failures, 60) << "the test fires too often on correct renders";
  RecordProperty("false_alarms_of_1000", failures);
}

TEST(FrameworkBlockTest, DefaultAlphaPassesAnotherSeed) {
  BlockTestResult r = block_t_test(synthetic(16, 7), synthetic(64, 8));
  EXPECT_TRUE(r.pass) << r.summary;
  EXPECT_NE(r.summary.find("all 12 blocks match"), std::string::npos) << r.summary;
  EXPECT_NEAR(r.overall_ratio.y, 1.0f, 0.02f);
}

TEST(FrameworkBlockTest, FivePercentTooDarkFailsAndSaysSo) {
  for (uint64_t seed : {11u, 12u, 13u}) {
    BlockTestResult r = block_t_test(synthetic(32, seed, 0.95f), synthetic(64, seed + 100));
    EXPECT_FALSE(r.pass) << r.summary;
    ASSERT_FALSE(r.failing.empty());
    EXPECT_LT(r.failing.front().t, 0.0);
    EXPECT_NE(r.summary.find("too dark"), std::string::npos) << r.summary;
    EXPECT_NEAR(r.overall_ratio.y, 0.95f, 0.02f);
  }
}

TEST(FrameworkBlockTest, TwiceTooBrightNamesTheBlockAndTheRatio) {
  BlockTestResult r = block_t_test(synthetic(16, 21, 2.0f), synthetic(64, 22));
  EXPECT_FALSE(r.pass);
  ASSERT_FALSE(r.failing.empty());
  // Every lit block differs; the black band's blocks (column 0) stay black and do not.
  EXPECT_EQ(r.failing.size(), 9u);
  for (const BlockDifference& b : r.failing) {
    EXPECT_NE(b.block_x, 0);
    EXPECT_NEAR(b.ratio.y, 2.0f, 0.1f);
  }
  EXPECT_NE(r.summary.find("% too bright"), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("block ("), std::string::npos) << r.summary;
}

TEST(FrameworkBlockTest, NaNFailsEvenInOnePixel) {
  RenderEstimate render = synthetic(16, 31);
  render.mean[5 * kWidth + 40].x = std::numeric_limits<float>::quiet_NaN();
  BlockTestResult r = block_t_test(render, synthetic(64, 32));
  EXPECT_FALSE(r.pass);
  EXPECT_TRUE(r.nonfinite);
  EXPECT_NE(r.summary.find("pixel (40,5)"), std::string::npos) << r.summary;

  RenderEstimate reference = synthetic(64, 32);
  reference.variance[0].z = std::numeric_limits<float>::infinity();
  r = block_t_test(synthetic(16, 31), reference);
  EXPECT_FALSE(r.pass);
  EXPECT_TRUE(r.nonfinite);
}

TEST(FrameworkBlockTest, SizeMismatchFails) {
  RenderEstimate render = synthetic(4, 41);
  RenderEstimate reference = synthetic(4, 42);
  reference.width = 48;
  reference.height = 64;
  BlockTestResult r = block_t_test(render, reference);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.summary.find("64x48"), std::string::npos) << r.summary;

  render.mean.pop_back();  // says 64x48 but has one pixel fewer
  r = block_t_test(render, synthetic(4, 42));
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.summary.find("malformed"), std::string::npos) << r.summary;
}

TEST(FrameworkBlockTest, ZeroVarianceExactMatchPassesAndAnyDifferenceFails) {
  // A noiseless image (every pixel one constant sample value, as a black background or a
  // directly seen light): identical passes without a division by zero...
  RenderEstimate flat;
  flat.width = kWidth;
  flat.height = kHeight;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    flat.mean.push_back(i % kWidth < 16 ? glm::vec3(0.0f) : glm::vec3(1.5f, 0.25f, 3.0f));
    flat.variance.push_back(glm::vec3(0.0f));
    flat.count.push_back(4.0f);
  }
  BlockTestResult same = block_t_test(flat, flat);
  EXPECT_TRUE(same.pass) << same.summary;
  EXPECT_FALSE(same.nonfinite);

  // ...and a difference that no noise explains fails, on the lit part and on the black part.
  RenderEstimate brighter = flat;
  brighter.mean[10 * kWidth + 40] *= 1.01f;
  BlockTestResult r = block_t_test(brighter, flat);
  EXPECT_FALSE(r.pass);
  ASSERT_EQ(r.failing.size(), 1u);
  EXPECT_EQ(r.failing[0].block_x, 2);
  EXPECT_EQ(r.failing[0].block_y, 0);
  EXPECT_NE(r.summary.find("too bright"), std::string::npos) << r.summary;

  RenderEstimate lit_background = flat;
  lit_background.mean[20 * kWidth + 3] = glm::vec3(0.01f);
  r = block_t_test(lit_background, flat);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.summary.find("block (0,1) is lit where the reference is black"), std::string::npos)
      << r.summary;
}

TEST(FrameworkBlockTest, RoundingIsNotADifferenceWhateverTheVariance) {
  // Two correct renders of a noiseless image (a normals view) computed in another order: every
  // pixel two float ulps brighter, the variance zero or nearly (1e-14: a t of thousands for a
  // rounding difference). Within the stated tolerance they match...
  RenderEstimate a, b;
  a.width = b.width = kWidth;
  a.height = b.height = kHeight;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    glm::vec3 v(0.5f + 0.4f * float(i % kWidth) / kWidth, 0.25f, 0.75f);
    a.mean.push_back(v);
    b.mean.push_back(v * (1.0f + 2.0f * std::numeric_limits<float>::epsilon()));
    glm::vec3 var(i % 3 == 0 ? 0.0f : 1e-14f);
    a.variance.push_back(var);
    b.variance.push_back(var);
    a.count.push_back(4.0f);
    b.count.push_back(4.0f);
  }
  BlockTestResult r = block_t_test(b, a);
  EXPECT_TRUE(r.pass) << r.summary;
  // ...and a difference ten times the tolerance in one block does not.
  RenderEstimate off = a;
  for (int y = 0; y < 16; ++y)
    for (int x = 32; x < 48; ++x) off.mean[size_t(y) * kWidth + x] *= 1.0f + 1e-4f;
  r = block_t_test(off, a);
  EXPECT_FALSE(r.pass);
  ASSERT_EQ(r.failing.size(), 1u);
  EXPECT_EQ(r.failing[0].block_x, 2);
  // A tolerance of zero is the exact comparison of old: the rounding fails again.
  BlockTestOptions exact;
  exact.relative_tolerance = exact.absolute_tolerance = 0.0;
  EXPECT_FALSE(block_t_test(b, a, exact).pass);
}

/// A flat grey image (every sample 0.5) but for an edge of 16 pixels in block (2,1), each of
/// whose samples is bright (1.0) one time in 16: `bright` of each edge pixel's `samples` are.
RenderEstimate grey_with_rare_edge(int samples, int bright) {
  RenderEstimate e;
  e.width = kWidth;
  e.height = kHeight;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      bool edge = x == 40 && y >= 16 && y < 32;
      PixelStats stats;
      for (int s = 0; s < samples; ++s) stats.add(glm::vec3(edge && s < bright ? 1.0f : 0.5f));
      e.mean.push_back(glm::vec3(stats.mean));
      e.variance.push_back(glm::vec3(stats.variance()));
      e.count.push_back(float(stats.count));
    }
  }
  return e;
}

TEST(FrameworkBlockTest, AFewSampleRenderThatMissedARareSampleIsChance) {
  // The reference (64 samples) saw each edge pixel's bright sample 4 times, as expected. A
  // correct 4-sample render expects 4 bright samples in the whole edge and sees none one time in
  // e^4 (about 2%): its edge has a variance of zero. Judged by the reference's variance alone
  // that is t = 8, a failure; with the reference's variance of one sample standing for the
  // render's as well, t = 2.
  RenderEstimate reference = grey_with_rare_edge(64, 4);
  BlockTestResult r = block_t_test(grey_with_rare_edge(4, 0), reference);
  EXPECT_TRUE(r.pass) << r.summary;
  // The same miss over 64 samples a pixel (64 bright samples expected, none seen) is no chance.
  r = block_t_test(grey_with_rare_edge(64, 0), reference);
  EXPECT_FALSE(r.pass) << r.summary;
  ASSERT_EQ(r.failing.size(), 1u);
  EXPECT_EQ(r.failing[0].block_x, 2);
  EXPECT_EQ(r.failing[0].block_y, 1);
}

TEST(FrameworkBlockTest, NoisyRenderAgainstNoiselessBlackStillPasses) {
  // The black band is noiseless in both; the lit part is noisy: zero variance in one block must
  // not make the whole test fragile.
  BlockTestResult r = block_t_test(synthetic(8, 51), synthetic(8, 52));
  EXPECT_TRUE(r.pass) << r.summary;
}

}  // namespace
}  // namespace pt
