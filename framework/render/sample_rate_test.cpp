// Not needed for the assignment.
// The sample-rate image shows exactly the samples each pixel took.
#include <gtest/gtest.h>

#include "framework/render/sample_rate.h"

namespace pt {
namespace {

TEST(FrameworkSampleRate, ColourOfEachPixelIsItsSampleCount) {
  Film film(4, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x)
      for (int i = 0; i < (y * 4 + x) * 8; ++i) film.at(x, y).add(glm::vec3(1.0f));
  Image rate = sample_rate_image(film, 56);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      glm::vec3 expected = sample_rate_colour(float((y * 4 + x) * 8) / 56.0f);
      EXPECT_EQ(rate.at(x, y), expected) << x << "," << y;
    }
  EXPECT_EQ(rate.at(0, 0), glm::vec3(0, 0, 1));  // no sample: blue
  EXPECT_EQ(rate.at(3, 1), glm::vec3(1, 0, 0));  // the maximum: red
}

TEST(FrameworkSampleRate, ColoursAreDistinctAlongTheScale) {
  glm::vec3 prev = sample_rate_colour(0.0f);
  for (int i = 1; i <= 10; ++i) {
    glm::vec3 c = sample_rate_colour(i / 10.0f);
    EXPECT_NE(c, prev);
    prev = c;
  }
}

}  // namespace
}  // namespace pt
