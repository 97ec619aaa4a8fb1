// Part 3, step 4 (importance): direct light by sampling the lights, against scenes whose answer
// is known, and the work it skips when the scene does not need it. Each test calls
// estimate_direct_importance itself, at a hit the rig found and shades with its own Lambertian.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/testing/draws_from_rng_only.h"
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

// The same plane seen from below, where the shading frame's z is the world's -z: directions must
// go between the frames (a ray needs world space, f and cosθ the local frame).
TEST(importance, plane_seen_from_below_is_rho_times_l) {
  test::expect_plane_seen_from_below_is_rho_times_l(false);
}

// The ceiling over a panel sees the light from behind: no light sample reaches it.
TEST(importance, ceiling_over_a_panel_is_dark) {
  EXPECT_EQ(test::ceiling_over_panel_light(false), glm::vec3(0.0f));
  // ...while the floor under it, which the panel faces, is lit (a dark ceiling alone proves
  // nothing: an estimate of zero everywhere has one).
  EXPECT_GT(test::floor_under_panel_light(false), 0.0);
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
  glm::vec3 L = test::reflected_at_hit(rig, false, r, rng);
  const double d2 = 1.0 + 4.0, cos_theta = 2.0 / std::sqrt(d2);
  const double expected = 0.5 / M_PI * 10.0 * cos_theta / d2;
  EXPECT_NEAR(L.x, expected, 1e-5 * expected)
      << test::ratio_hint(L.x, expected,
                          {{16.0, "the point light sampled -l (16) times and the samples summed?"},
                           {M_PI, "π times: I·cosθ/d² without the BSDF's 1/π?"},
                           {1.0 / cos_theta, "cosθ left out?"},
                           {std::sqrt(d2), "divided by d, not d²?"}});
  // A delta light takes one sample whatever -l says: one shadow ray.
  EXPECT_TRUE(rig.query.occluded_calls == 1)
      << rig.query.occluded_calls << " shadow rays: a point light is a delta light, one sample "
      << "(one shadow ray) whatever -l says (here 16)";
}

// Every light adds its own light: three point lights of different colours and powers over a
// plane, each estimated exactly, sum to Σ ρ/π · I cosθ / d² per channel. An estimate that
// averages over the lights (a third of this) or takes only one of them fails by a factor no
// rounding explains; a scene with one light cannot tell those apart from the sum.
TEST(importance, several_lights_add_their_light) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  struct Point {
    glm::vec3 at, intensity;
  };
  const Point points[] = {{{1.0f, 0.0f, 2.0f}, {10.0f, 2.0f, 0.5f}},
                          {{-1.5f, 0.5f, 1.0f}, {1.0f, 6.0f, 1.0f}},
                          {{0.0f, -2.0f, 3.0f}, {3.0f, 3.0f, 20.0f}}};
  glm::dvec3 expected(0.0);
  for (const Point& p : points) {
    Light l;
    l.kind = LightKind::point;
    l.position = p.at;
    l.radiance = p.intensity;
    s.lights.push_back(l);
    const double d2 = double(glm::dot(p.at, p.at)), cos_theta = p.at.z / std::sqrt(d2);
    expected += glm::dvec3(p.intensity) * (0.5 / M_PI * cos_theta / d2);
  }
  test::Rig rig(s);
  rig.ctx.light_samples = 4;
  Ray r;
  r.o = glm::vec3(0.0f, 0.0f, 3.0f);
  Rng rng(11);
  const glm::vec3 L = test::reflected_at_hit(rig, false, r, rng);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(L[c], expected[c], 1e-5 * expected[c])
        << "channel " << c << " under three point lights"
        << test::ratio_hint(L[c], expected[c],
                            {{1.0 / 3.0, "the lights averaged, not summed (each light adds its own light)?"}});
  EXPECT_EQ(rig.query.occluded_calls, 3) << "one shadow ray per point light (a delta light takes one sample)";
}

// A shadow ray runs from the point (started by spawn_shadow_ray, which offsets it by the hit's
// error bound only) to just short of the light: an occluder 1.5 cm above the floor, and a tile
// 0.5 mm above it right under the light, shadow it completely, and a ceiling 1 cm above a point
// light does not. A fixed epsilon (0.05, or even 0.001) starts the ray above the occluder (light
// leaks through); a shadow ray ending past the light meets the ceiling (a lit floor goes dark).
TEST(importance, shadow_rays_run_exactly_from_the_point_to_the_light) {
  Scene s;
  const uint32_t white = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, white);           // floor
  test::add_quad(s, {-1, -1, 0.015f}, {1, -1, 0.015f}, {1, 1, 0.015f}, {-1, 1, 0.015f}, white);  // slab
  test::add_quad(s, {-5, -5, 1.01f}, {5, -5, 1.01f}, {5, 5, 1.01f}, {-5, 5, 1.01f}, white);  // ceiling
  test::add_quad(s, {1.8f, -0.2f, 0.0005f}, {2.2f, -0.2f, 0.0005f}, {2.2f, 0.2f, 0.0005f},
                 {1.8f, 0.2f, 0.0005f}, white);  // a tile right under the light
  Light l;
  l.kind = LightKind::point;
  l.position = glm::vec3(2.0f, 0.0f, 1.0f);
  l.radiance = glm::vec3(10.0f);
  s.lights.push_back(l);
  test::Rig rig(s);
  Rng rng(5);
  Ray under;  // starts between the floor and the slab, looks down at the floor under the slab
  under.o = glm::vec3(0.0f, 0.1f, 0.01f);
  EXPECT_EQ(test::reflected_at_hit(rig, false, under, rng), glm::vec3(0.0f))
      << "a floor point 1.5 cm under an opaque slab got light: light leaking past an occluder (a "
         "shadow ray started with a fixed epsilon, not spawn_shadow_ray)?";
  Ray under_tile;  // starts between the floor and the tile, looks down at the floor under it
  under_tile.o = glm::vec3(2.0f, 0.05f, 0.0002f);
  EXPECT_EQ(test::reflected_at_hit(rig, false, under_tile, rng), glm::vec3(0.0f))
      << "a floor point 0.5 mm under an opaque tile, the light straight above, got light: light "
         "leaking past an occluder (a shadow ray started a fixed distance along, not by "
         "spawn_shadow_ray's error bound)?";
  Ray beside;  // a floor point clear of the slab, lit by the light 1 cm under the ceiling
  beside.o = glm::vec3(2.5f, 0.0f, 0.5f);
  const glm::vec3 L = test::reflected_at_hit(rig, false, beside, rng);
  const double d2 = 0.25 + 1.0, cos_theta = 1.0 / std::sqrt(d2);
  const double expected = 0.5 / M_PI * 10.0 * cos_theta / d2;
  EXPECT_NEAR(L.x, expected, 1e-4 * expected)
      << "a floor point in the open, a point light 1 cm under the ceiling"
      << (L.x == 0.0f ? ": no light: does the shadow ray end past the light, at the ceiling? (end "
                        "it short of the light: spawn_shadow_ray)"
                      : "");
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
    const glm::vec3 L = test::reflected_at_hit(rig, false, r, rng);
    EXPECT_GT(L.x, 0.0f);
    // A shadow ray is an any-hit query (LightSet::unoccluded), the camera ray the one nearest-hit
    // query; a student's own shadow test may ask either.
    const long shadow_rays = rig.query.intersect_calls - 1 + rig.query.occluded_calls;
    EXPECT_TRUE(shadow_rays == l)
        << shadow_rays << " shadow rays for one floor point under one area light with -l " << l
        << ": -l light samples of an area light, one shadow ray each";
  }
}

// What the scene does not need is not done: a shadow ray for a sample whose f is zero can only
// confirm a contribution of zero.
TEST(importance, a_black_surface_traces_no_shadow_rays) {
  {
    // A grey sphere under the same sky takes its shadow rays...
    Scene grey = test::sphere_under_sky(0.5f, 1.0f);
    test::Rig rig(grey);
    rig.ctx.light_samples = 8;
    Rng rng(1);
    Ray r;
    r.o = glm::vec3(0, 0, 3);
    EXPECT_GT(test::reflected_at_hit(rig, false, r, rng).x, 0.0f);
    EXPECT_GT(rig.query.occluded_calls + rig.query.intersect_calls - 1, 0);
  }
  // ...a black one, whose f is 0 whatever the direction, takes none.
  Scene s = test::sphere_under_sky(0.0f, 1.0f);
  test::Rig rig(s);
  rig.ctx.light_samples = 8;
  Rng rng(1);
  Ray r;
  r.o = glm::vec3(0, 0, 3);
  EXPECT_EQ(test::reflected_at_hit(rig, false, r, rng), glm::vec3(0.0f));
  EXPECT_EQ(rig.query.occluded_calls, 0)
      << "f = 0 for every direction (albedo 0): no shadow ray is needed, and none may be traced";
}

// Nor for a sample whose radiance is zero: over a grey floor (f not 0) a point light shines
// down and a spot light beside it shines up, away from the floor (its cone is the whole sphere,
// its falloff cos^1, so every light sample of it reaching the floor carries radiance 0). One
// shadow ray, the point light's, is all the estimate needs.
TEST(importance, a_light_sample_of_no_radiance_traces_no_shadow_ray) {
  Scene s;
  const uint32_t floor = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  Light down;
  down.kind = LightKind::point;
  down.position = glm::vec3(0.0f, 0.0f, 1.0f);
  down.radiance = glm::vec3(1.0f);
  Light away;
  away.kind = LightKind::spot;
  away.position = glm::vec3(0.4f, 0.0f, 1.0f);
  away.direction = glm::vec3(0.0f, 0.0f, 1.0f);
  away.radiance = glm::vec3(1.0f);
  away.falloff_degrees = 360.0f;
  away.falloff_exponent = 1.0f;
  s.lights = {down, away};
  test::Rig rig(s);
  Ray r;
  r.o = glm::vec3(0.1f, 0.2f, 0.5f);
  r.d = glm::vec3(0.0f, 0.0f, -1.0f);
  Rng rng(1);
  EXPECT_GT(test::reflected_at_hit(rig, false, r, rng).x, 0.0f);
  const long shadow_rays = rig.query.intersect_calls - 1 + rig.query.occluded_calls;
  EXPECT_EQ(shadow_rays, 1)
      << "two light samples, one of radiance 0 (the spot light shines away from the floor) while "
         "f is not (albedo 0.5): one shadow ray is needed, and only one may be traced";
}

// A closed box of CGL emitters with a diffuse colour beside their radiance: they glow and reflect
// nothing, so every light sample inside sees exactly their radiance.
TEST(importance, emitter_panels_reflect_nothing_in_a_closed_box) {
  test::expect_emitter_box_reflects_nothing(false);
}

// CBcoil's panel and its light disagree: light sampling samples the light's own rectangle with
// its radiance, not the panel the camera sees.
TEST(importance, floor_is_lit_by_the_lights_rectangle) {
  test::expect_floor_lit_by_the_lights_rectangle(false);
}

// rng is the estimate's only source of random numbers: every sample of the panel's light reaches
// the floor, each with its own distance and angle, so the answer depends on every number drawn.
TEST(importance, draws_from_rng_only) {
  Scene s = test::panel_under_ceiling();
  const uint32_t floor = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  test::Rig rig(s);
  rig.ctx.light_samples = 4;
  Ray r;
  r.o = glm::vec3(0.1f, -0.1f, 0.5f);
  r.d = glm::vec3(0.0f, 0.0f, -1.0f);
  test::expect_draws_from_rng_only("estimate_direct_importance", [&](Rng& rng) {
    return test::reflected_at_hit(rig, false, r, rng);
  });
}

}  // namespace
}  // namespace pt
