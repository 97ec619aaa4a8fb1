// Not needed for the assignment.
// A two-sided emissive panel seen from a centimetre away (CBempty's ceiling above its panel): light
// sampling's estimate of the irradiance there is close to the known answer in every batch of a
// thousand samples, and no sample's weight is unbounded.
#include "framework/lights/sampled_lights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "framework/sampling/rng.h"
#include "framework/testing/test_scenes.h"

namespace pt {
namespace {

// Irradiance at height h above the centre of an a × b rectangle of radiance L: four a/2 × b/2
// rectangles seen from above a corner, each of form factor
//   F = (1/2π) [X/√(1+X²) atan(Y/√(1+X²)) + Y/√(1+Y²) atan(X/√(1+Y²))],  X = a/2h, Y = b/2h,
// and E = π L · 4F.
double irradiance_above_centre(double a, double b, double h, double L) {
  const double X = 0.5 * a / h, Y = 0.5 * b / h;
  const double sx = std::sqrt(1.0 + X * X), sy = std::sqrt(1.0 + Y * Y);
  const double F = (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2.0 * M_PI);
  return M_PI * L * 4.0 * F;
}

TEST(FrameworkSampledLightsNearField, ATwoSidedPanelACentimetreAwayIsEstimatedWellInEveryBatch) {
  Scene s;
  const float L = 10.0f, h = 0.01f;
  const uint32_t glow = test::add_material(s, glm::vec3(0.0f), glm::vec3(L));
  test::add_quad(s, {-0.4f, -0.3f, 0.0f}, {0.4f, -0.3f, 0.0f}, {0.4f, 0.3f, 0.0f}, {-0.4f, 0.3f, 0.0f},
                 glow);
  const SampledLights lights(s);
  ASSERT_EQ(lights.lights().size(), 1u);
  ASSERT_EQ(lights.lights()[0].kind, SampledLightKind::mesh);
  test::DoubleQuery query(s);
  SurfaceHit at;
  at.p = glm::vec3(0.05f, 0.02f, h);
  at.ng = at.n = glm::vec3(0.0f, 0.0f, -1.0f);  // a ceiling facing the panel below it
  const double E = irradiance_above_centre(0.8, 0.6, h, L) ;
  ASSERT_NEAR(E, M_PI * L, 0.02 * M_PI * L);  // nearly the whole hemisphere glows
  Rng rng(5, 3);
  double largest = 0.0, worst = 0.0, total = 0.0;
  long inconsistent = 0;
  const int batches = 64, n = 1024;
  for (int batch = 0; batch < batches; ++batch) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const LightSample ls = lights.make_sample(0, at, rng.next_2d());
      if (!(ls.pdf > 0.0f)) continue;
      const double cos_p = std::max(0.0f, glm::dot(ls.wi, at.n));
      const double weight = double(ls.L.x) * cos_p / double(ls.pdf);
      sum += weight;
      largest = std::max(largest, weight);
      // The density is the one pdf() gives the ray that finds the same point.
      Ray r;
      r.o = at.p;
      r.d = ls.wi;
      SurfaceHit on;
      if (!query.intersect(r, &on) || std::abs(lights.pdf(0, at, ls.wi, &on) - ls.pdf) > 1e-3f * ls.pdf)
        ++inconsistent;
    }
    worst = std::max(worst, std::abs(sum / n - E) / E);
    total += sum;
  }
  // Area sampling put weights of L·A/h² (some 48,000 here) on one sample in a few thousand: most
  // batches were far too dark and a few far too bright.
  EXPECT_LT(worst, 0.15) << "the worst batch of " << n << " samples is off by " << 100 * worst
                         << "% (irradiance " << E << ")";
  EXPECT_NEAR(total / (double(n) * batches), E, 0.01 * E) << "the mean of all samples";
  EXPECT_LE(largest, 4.0 * M_PI * L) << "a light sample's weight L cos / pdf";
  EXPECT_EQ(inconsistent, 0) << "samples whose density is not pdf()'s";
}

}  // namespace
}  // namespace pt
