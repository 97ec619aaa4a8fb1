// A reference that is the mean of several renders (Part 5's course rule): the plain mean of their
// means, the pooled variance of one sample, the total count.
#include "grader/reference_mean.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "grader/tests/synthetic.h"

namespace pt::grader {
namespace {

RenderEstimate one_pixel(float mean, float variance, float count) {
  RenderEstimate e;
  e.width = e.height = 1;
  e.mean = {glm::vec3(mean)};
  e.variance = {glm::vec3(variance)};
  e.count = {count};
  return e;
}

TEST(GraderReferenceMean, EachRenderWeighsTheSameAndTheVarianceIsPooled) {
  // A render that stopped after 5 samples weighs as much as one that took 3: each is one draw of
  // the adaptive estimator, whose expectation the reference must have.
  const RenderEstimate m = mean_of_renders({one_pixel(1.0f, 4.0f, 5.0f), one_pixel(3.0f, 2.0f, 3.0f)});
  EXPECT_FLOAT_EQ(m.mean[0].x, 2.0f);
  EXPECT_FLOAT_EQ(m.variance[0].y, (4.0f * 4.0f + 2.0f * 2.0f) / 6.0f);  // (n - 1)-weighted
  EXPECT_FLOAT_EQ(m.count[0], 8.0f);
  // One sample says nothing of the variance: it is left out of the pool, not counted as zero.
  const RenderEstimate single = mean_of_renders({one_pixel(1.0f, 0.0f, 1.0f), one_pixel(2.0f, 3.0f, 4.0f)});
  EXPECT_FLOAT_EQ(single.variance[0].z, 3.0f);
  EXPECT_FLOAT_EQ(single.mean[0].x, 1.5f);
}

TEST(GraderReferenceMean, TheMeanOfManyRendersIsCloseToTheTruth) {
  // 16 renders of 16 samples: the mean's block means are within a few standard errors of the
  // truth, and variance / count is the variance of the mean (so the t-test's scale is right).
  std::vector<RenderEstimate> runs;
  for (uint64_t seed = 1; seed <= 16; ++seed) runs.push_back(testing::full_render(16, seed));
  const RenderEstimate m = mean_of_renders(runs);
  const RenderEstimate truth = testing::full_render(1 << 12, 99);
  EXPECT_TRUE(block_t_test(m, truth).pass) << block_t_test(m, truth).summary;
  EXPECT_FALSE(block_t_test(m, testing::full_render(1 << 12, 99, 1.02f)).pass)
      << "a 2% brighter truth went unnoticed: the mean's variance is too large";
}

TEST(GraderReferenceMean, RendersOfOtherSizesOrNoneAreRefused) {
  RenderEstimate wide = one_pixel(1.0f, 1.0f, 2.0f);
  wide.width = 2;
  EXPECT_THROW(mean_of_renders({one_pixel(1.0f, 1.0f, 2.0f), wide}), std::invalid_argument);
  EXPECT_THROW(mean_of_renders({}), std::invalid_argument);
}

}  // namespace
}  // namespace pt::grader
