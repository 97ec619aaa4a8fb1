// Not needed for the assignment.
// The chi-square harness itself: a test must be able to fail.
#include "framework/sampling/chi2_test_util.h"

#include <gtest/gtest.h>

#include "framework/sampling/warp.h"

namespace pt {
namespace {

// The cosine sampler checked against the uniform density is rejected.
TEST(FrameworkChiSquare, RejectsAWrongDensity) {
  Chi2Result r = chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_cosine_hemisphere(u); return true; },
      [](const glm::vec3& w) { return double(uniform_hemisphere_pdf(w)); }, Frame({0, 0, 1}));
  EXPECT_LT(r.p_value, 0.01) << r.summary;
  EXPECT_FALSE(chi2_fits(r)) << r.summary;
}

}  // namespace
}  // namespace pt
