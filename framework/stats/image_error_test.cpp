// Not needed for the assignment.
// Relative MSE and RMSE on images whose errors are known by hand.
#include "framework/stats/image_error.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

namespace pt {
namespace {

TEST(ConvergenceError, RelativeMseOfAKnownDifference) {
  // Reference 1 everywhere, image 1.1 in every channel: each term is 0.01 / (1 + ε).
  Image ref(4, 3, glm::vec3(1.0f)), img(4, 3, glm::vec3(1.1f));
  const double d = double(1.1f) - 1.0;
  EXPECT_NEAR(relative_mse(img, ref), d * d / (1.0 + kRelMseEpsilon), 1e-12);
  EXPECT_NEAR(rmse(img, ref), d, 1e-7);
}

TEST(ConvergenceError, RelativeMseWeighsEachPixelByItsReference) {
  // One bright pixel off by 1 and one black pixel off by 0.1: the black one's ε keeps it finite,
  // and relative error makes it count as much as the bright one's 10 % miss would.
  Image ref(2, 1), img(2, 1);
  ref.at(0, 0) = glm::vec3(10.0f);
  img.at(0, 0) = glm::vec3(11.0f);
  img.at(1, 0) = glm::vec3(0.1f, 0.0f, 0.0f);
  const double bright = 1.0 / (100.0 + kRelMseEpsilon);
  const double dark = double(0.1f) * double(0.1f) / kRelMseEpsilon;
  EXPECT_NEAR(relative_mse(img, ref), (3.0 * bright + dark) / 6.0, 1e-9);
  EXPECT_NEAR(rmse(img, ref), std::sqrt((3.0 + double(0.1f) * double(0.1f)) / 6.0), 1e-7);
}

TEST(ConvergenceError, IdenticalImagesHaveNoError) {
  Image a(3, 2, glm::vec3(0.25f, 0.5f, 2.0f));
  EXPECT_EQ(relative_mse(a, a), 0.0);
  EXPECT_EQ(rmse(a, a), 0.0);
}

TEST(ConvergenceError, MismatchedOrNonFiniteImagesAreRefused) {
  Image a(3, 2), b(2, 3);
  EXPECT_THROW(relative_mse(a, b), std::invalid_argument);
  EXPECT_THROW(rmse(Image(), Image()), std::invalid_argument);
  Image nan(3, 2);
  nan.at(1, 1).y = std::numeric_limits<float>::quiet_NaN();
  try {
    relative_mse(nan, a);
    FAIL() << "a NaN pixel must not read as an error of some size";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("(1, 1)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pt
