// Scenes the Part 3 step tests share, each with a known answer, and direct light alone as a
// renderer computes it (pipeline/3-direct: emission plus one_bounce_radiance, no Part 4).
#pragma once

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "framework/testing/lighting_rig.h"
#include "parts/3-direct/direct_lighting.h"
#include "pipeline/3-direct/direct_integrator.h"

namespace pt::test {

/// Significance of each known-answer t-test.
constexpr double kDirectAlpha = 0.001;

/// Direct light only (Part 3's estimators, without Part 4): emission plus one_bounce_radiance.
inline glm::vec3 direct_only(const LightingContext& ctx, const Ray& ray, Rng& rng) {
  return estimate_direct_illumination(ctx, ray, rng);
}

/// A diffuse unit sphere of albedo rho at the origin under a uniform sky of radiance L.
inline Scene sphere_under_sky(float rho, float L) {
  Scene s;
  uint32_t m = add_material(s, glm::vec3(rho));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  s.lights.push_back(ambient_light(glm::vec3(L)));
  return s;
}

/// An area light's panel hangs just under a ceiling, facing down (as in the course's Cornell
/// boxes). The light shines down only, so its panel must glow on that side only: seen from
/// above, and for the ceiling over it, whichever estimator is used.
inline Scene panel_under_ceiling() {
  Scene s;
  const uint32_t white = add_material(s, glm::vec3(0.5f));
  const uint32_t glow = add_material(s, glm::vec3(0.0f), glm::vec3(5.0f));
  add_quad(s, {-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}, white);  // ceiling
  add_quad(s, {-0.5f, -0.5f, 0.99f}, {0.5f, -0.5f, 0.99f}, {0.5f, 0.5f, 0.99f},
           {-0.5f, 0.5f, 0.99f}, glow);  // panel
  Light l;
  l.kind = LightKind::area;
  l.radiance = glm::vec3(5.0f);
  l.position = glm::vec3(0.0f, 0.0f, 0.99f);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  l.edge_u = glm::vec3(1.0f, 0.0f, 0.0f);
  l.edge_v = glm::vec3(0.0f, 1.0f, 0.0f);
  s.lights.push_back(l);
  return s;
}

/// The mean radiance of a floor point under the panel of panel_under_ceiling(), over `n`
/// estimates: lit, by either estimator (the panel's lit side faces the floor).
inline double floor_under_panel_light(bool hemisphere, int n = 400) {
  Scene s = panel_under_ceiling();
  const uint32_t floor = add_material(s, glm::vec3(0.5f));
  add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  Rig rig(s);
  rig.ctx.hemisphere = hemisphere;
  Rng rng(11);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    Ray r;
    r.o = glm::vec3(0.1f, -0.1f, 0.5f);
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    sum += direct_only(rig.ctx, r, rng).x;
  }
  return sum / n;
}

/// A diffuse plane of albedo 0.3 facing a uniform sky of radiance 1.5.
inline Scene plane_under_sky() {
  Scene s;
  uint32_t m = add_material(s, glm::vec3(0.3f));
  add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  s.lights.push_back(ambient_light(glm::vec3(1.5f)));
  return s;
}

/// A ray from above the plane, at a random point of a unit square over its centre.
inline Ray ray_at_plane(Rng& g) {
  Ray r;
  r.o = glm::vec3(g.next_float() - 0.5f, g.next_float() - 0.5f, 1.0f);
  r.d = glm::normalize(glm::vec3(0.1f, -0.2f, -1.0f));
  return r;
}

/// A convex diffuse sphere of albedo ρ under a uniform sky L never sees itself: L_out = ρL, by
/// hemisphere or light sampling. Expects it within chance.
inline void expect_sphere_under_sky_is_rho_times_l(bool hemisphere) {
  const float rho = 0.6f, L = 2.0f;
  Rig rig(sphere_under_sky(rho, L));
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.light_samples = 4;
  auto xs = sample_values([&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
                          ray_at_unit_sphere, 20000, 11);
  auto c = t_test_mean(xs, rho * L, kDirectAlpha);
  EXPECT_TRUE(c.pass) << "mean " << c.mean << " ± " << c.stderr_ << ", expected " << rho * L;
}

/// A diffuse plane facing a uniform sky, seen from above: ρL as well (it sees only sky), by
/// hemisphere or light sampling. Expects it within chance.
inline void expect_plane_under_sky_is_rho_times_l(bool hemisphere) {
  Rig rig(plane_under_sky());
  rig.ctx.hemisphere = hemisphere;
  auto xs = sample_values([&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
                          ray_at_plane, 20000, 5);
  auto c = t_test_mean(xs, 0.3 * 1.5, kDirectAlpha);
  EXPECT_TRUE(c.pass) << "mean " << c.mean << " ± " << c.stderr_ << ", expected 0.45";
}

/// The sum of 64 one_bounce_radiance samples at the point of the ceiling over the panel, seen
/// from below, by hemisphere or light sampling (64 samples each).
inline glm::vec3 ceiling_over_panel_light(bool hemisphere) {
  Rig rig(panel_under_ceiling());
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.light_samples = 64;
  Ray up;
  up.o = glm::vec3(0.1f, 0.2f, 0.995f);
  up.d = glm::vec3(0.0f, 0.0f, 1.0f);
  SurfaceHit hit;
  if (!rig.query.intersect(up, &hit)) return glm::vec3(-1.0f);  // never: the ceiling is there
  ShadingPoint sp(rig.ctx.scene, up, hit);
  Rng rng(5);
  glm::vec3 sum(0.0f);
  for (int i = 0; i < 64; ++i) sum += one_bounce_radiance(rig.ctx, sp, rng);
  return sum;
}

}  // namespace pt::test
