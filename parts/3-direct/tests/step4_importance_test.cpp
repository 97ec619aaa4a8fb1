// Part 3, step 4 (importance): direct light by sampling the lights, against scenes whose answer
// is known, and the work it skips when the scene does not need it.
#include <gtest/gtest.h>

#include <cmath>

#include "parts/3-direct/tests/direct_scenes.h"

namespace pt {
namespace {

// A convex diffuse sphere of albedo ρ under a uniform sky L never sees itself: L_out = ρL.
TEST(importance, sphere_under_uniform_sky_is_rho_times_l) {
  test::expect_sphere_under_sky_is_rho_times_l(false);
}

// A diffuse plane facing a uniform sky, seen from above: ρL as well (it sees only sky).
TEST(importance, plane_under_uniform_sky_is_rho_times_l) {
  test::expect_plane_under_sky_is_rho_times_l(false);
}

// The ceiling over a panel sees the light from behind: no light sample reaches it.
TEST(importance, ceiling_over_a_panel_is_dark) {
  EXPECT_EQ(test::ceiling_over_panel_light(false), glm::vec3(0.0f));
}

// One point light over a plane: the estimate is exact, ρ/π · I cosθ / d².
TEST(importance, point_light_over_plane_is_exact) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  Light l;
  l.kind = LightKind::point;
  l.position = glm::vec3(1.0f, 0.0f, 2.0f);
  l.radiance = glm::vec3(10.0f);
  s.lights.push_back(l);
  test::Rig rig(s);
  rig.ctx.light_samples = 16;
  Ray r;
  r.o = glm::vec3(0.0f, 0.0f, 3.0f);
  Rng rng(1);
  glm::vec3 L = test::direct_only(rig.ctx, r, rng);
  const double d2 = 1.0 + 4.0, cos_theta = 2.0 / std::sqrt(d2);
  const double expected = 0.5 / M_PI * 10.0 * cos_theta / d2;
  EXPECT_NEAR(L.x, expected, 1e-5 * expected);
  // A delta light takes one sample whatever -l says: one shadow ray.
  EXPECT_EQ(rig.query.occluded_calls, 1);
}

// -l is the number of samples per area light: a floor point under the panel takes exactly that
// many (one shadow ray each), and the estimate averages them. One sample whatever -l says gives
// the right mean with -l times the variance, which no mean comparison sees.
TEST(importance, an_area_light_takes_l_samples) {
  Scene s = test::panel_under_ceiling();
  const uint32_t floor = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  for (int l : {1, 4, 7}) {
    SCOPED_TRACE("-l " + std::to_string(l));
    test::Rig rig(s);
    rig.ctx.light_samples = l;
    Ray r;
    r.o = glm::vec3(0.1f, 0.2f, 0.5f);  // between floor and panel, looking down at the floor
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    Rng rng(3);
    const glm::vec3 L = test::direct_only(rig.ctx, r, rng);
    EXPECT_GT(L.x, 0.0f);
    // A shadow ray to a light with an emitting panel is a nearest-hit query (the panel it may hit
    // is the light's own face, LightSet::unoccluded); the camera ray is the one other query.
    EXPECT_EQ(rig.query.intersect_calls - 1 + rig.query.occluded_calls, l)
        << "shadow rays for one floor point under one area light: one per light sample";
  }
}

// What the scene does not need is not done.
TEST(importance, no_environment_means_a_miss_is_black_at_once) {
  Scene s;
  Light l;
  l.kind = LightKind::point;
  s.lights.push_back(l);
  test::Rig rig(s);
  Rng rng(1);
  Ray r;
  EXPECT_EQ(test::direct_only(rig.ctx, r, rng), glm::vec3(0.0f));
  EXPECT_EQ(rig.query.intersect_calls, 1);
  EXPECT_EQ(rig.query.occluded_calls, 0);
}

TEST(importance, a_black_surface_traces_no_shadow_rays) {
  Scene s = test::sphere_under_sky(0.0f, 1.0f);
  test::Rig rig(s);
  rig.ctx.light_samples = 8;
  Rng rng(1);
  Ray r;
  r.o = glm::vec3(0, 0, 3);
  EXPECT_EQ(test::direct_only(rig.ctx, r, rng), glm::vec3(0.0f));
  EXPECT_EQ(rig.query.occluded_calls, 0);
}

}  // namespace
}  // namespace pt
