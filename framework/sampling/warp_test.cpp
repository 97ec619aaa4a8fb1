// Not needed for the assignment.
// Chi-square goodness-of-fit of the warps against the density each claims, at significance 0.01
// per test (Nori's level); and each density integrates to 1.
#include "framework/sampling/warp.h"

#include <gtest/gtest.h>

#include <cmath>

#include "framework/math/frame.h"
#include "framework/sampling/chi2_test_util.h"

namespace pt {
namespace {

TEST(FrameworkWarp, UniformHemisphereFitsItsDensity) {
  const Chi2Result r = chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_hemisphere(u); return true; },
      [](const glm::vec3& w) { return double(uniform_hemisphere_pdf(w)); }, Frame({0, 0, 1}));
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

TEST(FrameworkWarp, CosineHemisphereFitsItsDensity) {
  const Chi2Result r = chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_cosine_hemisphere(u); return true; },
      [](const glm::vec3& w) { return double(cosine_hemisphere_pdf(w)); }, Frame({0, 0, 1}));
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

TEST(FrameworkWarp, UniformSphereFitsItsDensity) {
  const Chi2Result r = chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_sphere(u); return true; },
      [](const glm::vec3&) { return double(uniform_sphere_pdf()); }, Frame({0, 0, 1}));
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

TEST(FrameworkWarp, UniformConeFitsItsDensity) {
  // 1 − cosθmax = 0.25: the rim at cosθ = 0.75 is an edge of the test's grid, so the midpoint
  // quadrature integrates every cell exactly.
  const float one_minus_cos = 0.25f;
  const Chi2Result r = chi2_direction_test(
      [&](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_cone(u, one_minus_cos); return true; },
      [&](const glm::vec3& w) {
        return w.z >= 1.0f - one_minus_cos ? double(uniform_cone_pdf(one_minus_cos)) : 0.0;
      },
      Frame({0, 0, 1}));
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

}  // namespace
}  // namespace pt
