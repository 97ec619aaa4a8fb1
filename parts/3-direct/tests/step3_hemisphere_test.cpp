// Part 3, step 3 (hemisphere): direct light by uniform hemisphere sampling, against scenes whose
// answer is known. Each test calls estimate_direct_hemisphere itself, at a hit the rig found and
// shades with its own Lambertian. It rests on no other step: the light its rays meet is the
// LightSet's (radiance_along), as light sampling samples it.
#include <gtest/gtest.h>

#include "framework/testing/draws_from_rng_only.h"
#include "parts/3-direct/tests/direct_scenes.h"

namespace pt {
namespace {

// A convex diffuse sphere of albedo ρ under a uniform sky L never sees itself: L_out = ρL.
TEST(hemisphere, sphere_under_uniform_sky_is_rho_times_l) {
  test::expect_sphere_under_sky_is_rho_times_l(true);
}

// A diffuse plane facing a uniform sky, seen from above: ρL as well (it sees only sky).
TEST(hemisphere, plane_under_uniform_sky_is_rho_times_l) {
  test::expect_plane_under_sky_is_rho_times_l(true);
}

// The same plane seen from below, where the shading frame's z is the world's -z: directions must
// go between the frames (a ray needs world space, f and cosθ the local frame).
TEST(hemisphere, plane_seen_from_below_is_rho_times_l) {
  test::expect_plane_seen_from_below_is_rho_times_l(true);
}

// Most hemisphere directions from the ceiling's point meet the panel's back 1 cm below: they
// must bring nothing, exactly as light sampling (which sees the light from behind) says.
TEST(hemisphere, ceiling_over_a_panel_is_dark) {
  EXPECT_EQ(test::ceiling_over_panel_light(true), glm::vec3(0.0f));
  // ...while the floor under it, which the panel faces, is lit (a dark ceiling alone proves
  // nothing: an estimate of zero everywhere has one).
  EXPECT_GT(test::floor_under_panel_light(true), 0.0);
}

// A closed box of CGL emitters with a diffuse colour beside their radiance: they glow and reflect
// nothing, so every direction inside sees exactly their radiance.
TEST(hemisphere, emitter_panels_reflect_nothing_in_a_closed_box) {
  test::expect_emitter_box_reflects_nothing(true);
}

// CBcoil's panel and its light disagree: the floor under them is lit by the light's own
// rectangle with its radiance, as light sampling lights it, not by the panel the camera sees.
TEST(hemisphere, floor_is_lit_by_the_lights_rectangle) {
  test::expect_floor_lit_by_the_lights_rectangle(true);
}

// rng is the estimate's only source of random numbers: under a uniform sky every direction
// brings light, weighted by its own cosθ, so the answer depends on every number drawn.
TEST(hemisphere, draws_from_rng_only) {
  test::Rig rig(test::plane_under_sky());
  rig.ctx.light_samples = 4;
  Rng g(7);
  const Ray r = test::ray_at_plane(g);
  test::expect_draws_from_rng_only("estimate_direct_hemisphere", [&](Rng& rng) {
    return test::reflected_at_hit(rig, true, r, rng);
  });
}

}  // namespace
}  // namespace pt
