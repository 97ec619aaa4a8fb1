// Not needed for the assignment.
// The specular BSDFs' sampling: glass chooses reflection with the Fresnel probability.
#include "framework/bsdf/specular.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "framework/sampling/rng.h"

namespace pt {
namespace {

// A two-cell goodness of fit (binomial), at significance 0.01, and each choice's weight is
// reflectance or transmittance scaled for radiance.
TEST(FrameworkGlass, ChoosesReflectionWithFresnelProbability) {
  GlassBsdf glass(glm::vec3(1.0f), glm::vec3(1.0f), 1.5f);
  const glm::vec3 wo = glm::normalize(glm::vec3(0.8f, 0.0f, 0.3f));
  const double F = fresnel_dielectric(wo.z, 1.5f);
  ASSERT_GT(F, 0.05);
  ASSERT_LT(F, 0.95);
  Rng rng(3);
  const int n = 40000;
  int reflected = 0;
  for (int i = 0; i < n; ++i) {
    glm::vec3 wi;
    float pdf;
    glm::vec3 f = glass.sample_f(wo, rng.next_2d(), &wi, &pdf);
    ASSERT_GT(pdf, 0.0f);
    glm::vec3 weight = f * std::abs(wi.z) / pdf;
    if (wi.z > 0) {
      ++reflected;
      EXPECT_NEAR(weight.x, 1.0f, 1e-4f);
    } else {
      EXPECT_NEAR(weight.x, 1.0f / (1.5f * 1.5f), 1e-4f);
    }
  }
  double expected = F * n, sd = std::sqrt(n * F * (1 - F));
  EXPECT_LT(std::abs(reflected - expected) / sd, 2.576) << "F = " << F << ", reflected " << reflected;
}

}  // namespace
}  // namespace pt
