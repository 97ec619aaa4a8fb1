// Part 3, step 3 (hemisphere): direct light by uniform hemisphere sampling, against scenes whose
// answer is known.
#include <gtest/gtest.h>

#include "parts/3-direct/tests/direct_scenes.h"

namespace pt {
namespace {

// A convex diffuse sphere of albedo ρ under a uniform sky L never sees itself: L_out = ρL.
TEST(hemisphere, sphere_under_uniform_sky_is_rho_times_l) {
  const float rho = 0.6f, L = 2.0f;
  test::Rig rig(test::sphere_under_sky(rho, L));
  rig.ctx.hemisphere = true;
  rig.ctx.light_samples = 4;
  auto xs = test::sample_values(
      [&](const Ray& r, Rng& g) { return test::direct_only(rig.ctx, r, g); },
      test::ray_at_unit_sphere, 20000, 11);
  auto c = test::t_test_mean(xs, rho * L, test::kDirectAlpha);
  EXPECT_TRUE(c.pass) << "mean " << c.mean << " ± " << c.stderr_ << ", expected " << rho * L;
}

// A diffuse plane facing a uniform sky, seen from above: ρL as well (it sees only sky).
TEST(hemisphere, plane_under_uniform_sky_is_rho_times_l) {
  test::Rig rig(test::plane_under_sky());
  rig.ctx.hemisphere = true;
  auto xs = test::sample_values(
      [&](const Ray& r, Rng& g) { return test::direct_only(rig.ctx, r, g); }, test::ray_at_plane,
      20000, 5);
  auto c = test::t_test_mean(xs, 0.3 * 1.5, test::kDirectAlpha);
  EXPECT_TRUE(c.pass) << "mean " << c.mean << " ± " << c.stderr_ << ", expected 0.45";
}

// Most hemisphere directions from the ceiling's point meet the panel's back 1 cm below: they
// must bring nothing, exactly as light sampling (which sees the light from behind) says.
TEST(hemisphere, ceiling_over_a_panel_is_dark) {
  EXPECT_EQ(test::ceiling_over_panel_light(true), glm::vec3(0.0f));
}

}  // namespace
}  // namespace pt
