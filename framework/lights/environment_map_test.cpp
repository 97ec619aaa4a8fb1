// Not needed for the assignment.
// The environment map samples directions by its pixels' power: chi-square against the density
// it claims, at significance 0.01, and the density integrates to 1.
#include "framework/lights/environment_map.h"

#include <gtest/gtest.h>

#include <vector>

#include "framework/math/frame.h"
#include "framework/sampling/chi2_test_util.h"

namespace pt {
namespace {

TEST(FrameworkEnvironmentMap, SamplesFitTheirDensity) {
  EnvironmentMap env;
  std::vector<glm::vec3> px(16 * 8);
  // Black polar rows: the density per steradian has a 1/sinθ factor there that the midpoint
  // quadrature of the test could not integrate accurately.
  for (int i = 0; i < int(px.size()); ++i)
    px[i] = (i < 16 || i >= 7 * 16) ? glm::vec3(0.0f) : glm::vec3(float(1 + (i * 7) % 5));
  px[3 * 16 + 5] = glm::vec3(50.0f);  // a sun
  env.set_pixels(16, 8, px);
  Chi2Options opt;
  opt.quadrature = 48;  // edges cut cells: a fine quadrature keeps their expected share exact
  const Chi2Result r = chi2_direction_test(
      [&](glm::vec2 u, glm::vec3* w) {
        float pdf;
        *w = env.sample(u, &pdf);
        return pdf > 0.0f;
      },
      [&](const glm::vec3& w) { return double(env.pdf(w)); }, Frame({0, 1, 0}), opt);
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

}  // namespace
}  // namespace pt
