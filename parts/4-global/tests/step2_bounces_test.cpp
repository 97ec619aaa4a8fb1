// Part 4, step 2 (bounces): paths of many bounces against scenes whose answer is known at every
// depth, bounce selection, specular spheres; and never a NaN, on the cases that divide by zero in
// careless code (zero-area lights, back-facing lights, grazing bounces, degenerate normals).
// Every test calls at_least_one_bounce_radiance at the hit the rig finds (not step 1's
// estimate_global_illumination), with Russian roulette off (step 3's) and without MIS (step 4's).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "framework/testing/draws_from_rng_only.h"
#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

// Convex: the sphere never sees itself, so every depth gives ρL.
TEST(bounces, sphere_under_uniform_sky_is_rho_times_l_at_every_depth) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.6f));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  s.lights.push_back(test::ambient_light(glm::vec3(2.0f)));
  test::Rig rig(s);
  rig.ctx.russian_roulette = false;
  for (int depth = 1; depth <= 5; ++depth) {
    rig.ctx.max_depth = depth;
    test::expect_mean(
        test::sample_values(test::bounced(rig.ctx), test::ray_at_unit_sphere, 10000, depth), 1.2,
        "depth " + std::to_string(depth),
        {{2.0, "twice: light counted both by light sampling and when a bounce ray meets it?"}});
  }
}

// Inside a closed box of albedo ρ emitting E everywhere the camera sees E(1 − ρ^(m+1))/(1 − ρ)
// at depth m without Russian roulette: after the E it sees directly, the bounces bring
// E(ρ + ... + ρ^m) = Eρ(1 − ρ^m)/(1 − ρ); and only the m-th bounce gives ρ^m E.
TEST(bounces, enclosure_at_depth_m_without_russian_roulette) {
  const double rho = 0.5, E = 1.0;
  test::Rig rig(test::enclosure(float(rho), float(E)));
  rig.ctx.russian_roulette = false;
  for (int m = 1; m <= 4; ++m) {
    rig.ctx.max_depth = m;
    const double bounces = E * rho * (1 - std::pow(rho, m)) / (1 - rho);
    test::expect_mean(
        test::sample_values(test::bounced(rig.ctx), test::ray_from_inside, 4000, 10 + m), bounces,
        "depth " + std::to_string(m) + " (the bounces' light, after the E seen directly)",
        {{(bounces + E * rho * (1 - std::pow(rho, m - 1)) / (1 - rho)) / bounces,
          "each vertex's own emission added as well as the light sampled there (light counted "
          "twice)?"},
         {E * rho * (1 - std::pow(rho, m + 1)) / (1 - rho) / bounces,
          "one bounce too many (depth off by one)?"},
         {E * rho * (1 - std::pow(rho, m - 1)) / (1 - rho) / bounces,
          "one bounce too few (depth off by one)?"}});
    rig.ctx.only_bounce = m;
    rig.ctx.max_depth = 4;
    test::expect_mean(
        test::sample_values(test::bounced(rig.ctx), test::ray_from_inside, 4000, 20 + m),
        E * std::pow(rho, m), "only bounce " + std::to_string(m),
        {{(1 - std::pow(rho, m + 1)) / (1 - rho) / std::pow(rho, m) - 1 / std::pow(rho, m),
          "the bounces up to K summed, not bounce K alone?"}});
    rig.ctx.only_bounce = -1;
  }
}

// A lossless glass sphere or a mirror of reflectance R in a uniform sky: L and RL.
TEST(bounces, specular_spheres_under_uniform_sky) {
  for (MaterialKind kind : {MaterialKind::glass, MaterialKind::mirror}) {
    Scene s;
    uint32_t m = test::add_material(s, glm::vec3(0.0f), glm::vec3(0.0f), kind);
    s.materials[m].reflectance = glm::vec3(kind == MaterialKind::mirror ? 0.8f : 1.0f);
    s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
    s.lights.push_back(test::ambient_light(glm::vec3(1.0f)));
    test::Rig rig(s);
    rig.ctx.max_depth = 100;
    rig.ctx.russian_roulette = false;
    test::expect_mean(
        test::sample_values(test::bounced(rig.ctx), test::ray_at_unit_sphere, 10000, 9),
        kind == MaterialKind::mirror ? 0.8 : 1.0, to_string(kind));
  }
}

// A mirror floor under CBcoil's panel and light, which disagree: the camera sees the panel in
// the mirror with the radiance light sampling gives it, the light's, by light and hemisphere
// sampling alike (MIS: step 4).
TEST(bounces, a_mirror_shows_the_panel_with_its_lights_radiance) {
  using P = test::DisagreeingPanel;
  EXPECT_NEAR(test::panel_in_a_mirror(false, false).x, P::kLightRadiance, 1e-4f) << "light sampling";
  EXPECT_NEAR(test::panel_in_a_mirror(true, false).x, P::kLightRadiance, 1e-4f) << "hemisphere";
}

// --- Never a NaN: the full estimator (depth 5, every strategy) ---------------------------------

// Estimates the bounced light at the hits of `n` random rays at the scene, by light and by
// hemisphere sampling (MIS is step 4's, Russian roulette step 3's: both off), and fails on the
// first non-finite or negative value, or when no strategy sees any light at all (every scene here
// has light the floor can see, if only by light sampling: zero is finite too, so an estimate of
// zero everywhere proves nothing).
void expect_all_finite(const Scene& scene, const std::function<Ray(Rng&)>& make_ray, int n = 3000) {
  test::Rig rig(scene);
  rig.ctx.max_depth = 5;
  rig.ctx.light_samples = 2;
  rig.ctx.russian_roulette = false;
  double sum = 0.0;
  for (int mode = 0; mode < 2; ++mode) {
    rig.ctx.hemisphere = mode == 1;
    Rng rng(uint64_t(mode) + 1, 5);
    for (int i = 0; i < n; ++i) {
      Ray r = make_ray(rng);
      glm::vec3 L = test::bounced_at_hit(rig.ctx, r, rng);
      for (int c = 0; c < 3; ++c)
        ASSERT_TRUE(std::isfinite(L[c]) && L[c] >= 0.0f)
            << "mode " << mode << ", ray " << i << ": (" << L.x << ", " << L.y << ", " << L.z << ")";
      sum += double(L.x) + L.y + L.z;
    }
  }
  EXPECT_GT(sum, 0.0) << 2 * n << " rays at a lit scene all came back black";
}

Ray ray_at_floor(Rng& g) {
  Ray r;
  r.o = glm::vec3(0.0f, 0.0f, 2.0f);
  r.d = glm::normalize(glm::vec3(g.next_float() - 0.5f, g.next_float() - 0.5f, -1.0f));
  return r;
}

Scene floor_scene() {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.7f));
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, m);
  return s;
}

TEST(bounces, no_nan_with_zero_area_lights) {
  Scene s = floor_scene();
  Light l;
  l.kind = LightKind::area;
  l.position = glm::vec3(0, 0, 1);
  l.edge_u = glm::vec3(0.0f);  // no area
  s.lights.push_back(l);
  uint32_t lamp = test::add_material(s, glm::vec3(0.5f), glm::vec3(5.0f));
  test::add_triangle(s, {0, 0, 1}, {1, 1, 1}, {2, 2, 1}, lamp);  // collinear corners
  s.spheres.push_back(Sphere{glm::vec3(0, 0, 1), 0.0f, lamp});   // a point of a sphere
  Light ok;
  ok.kind = LightKind::point;
  ok.position = glm::vec3(0, 0, 1);
  s.lights.push_back(ok);
  LightSet lights(s);
  EXPECT_EQ(lights.lights().size(), 1u) << "only the point light can emit";
  expect_all_finite(s, ray_at_floor);
}

TEST(bounces, no_nan_with_back_facing_and_edge_on_lights) {
  Scene s = floor_scene();
  Light up;  // an area light facing away from the floor
  up.kind = LightKind::area;
  up.position = glm::vec3(0, 0, 1);
  up.direction = glm::vec3(0, 0, 1);
  s.lights.push_back(up);
  Light edge_on = up;  // a light in the floor's plane, seen only edge-on
  edge_on.position = glm::vec3(3, 0, 0);
  edge_on.edge_u = glm::vec3(1, 0, 0);
  edge_on.edge_v = glm::vec3(0, 0, 1);
  edge_on.direction = glm::vec3(0, 1, 0);
  s.lights.push_back(edge_on);
  Light at_surface;  // a point light on the floor itself: distance zero for some shading points
  at_surface.kind = LightKind::point;
  at_surface.position = glm::vec3(0, 0, 0);
  s.lights.push_back(at_surface);
  Light above = at_surface;  // and one that does light the floor
  above.position = glm::vec3(0.3f, 0.2f, 1.5f);
  s.lights.push_back(above);
  expect_all_finite(s, ray_at_floor);
}

TEST(bounces, no_nan_with_grazing_rays_and_bounces) {
  Scene s = floor_scene();
  s.lights.push_back(test::ambient_light(glm::vec3(1.0f)));
  uint32_t glass = test::add_material(s, glm::vec3(0), glm::vec3(0), MaterialKind::glass);
  uint32_t mirror = test::add_material(s, glm::vec3(0), glm::vec3(0), MaterialKind::mirror);
  s.spheres.push_back(Sphere{glm::vec3(-1, 0, 0.5f), 0.5f, glass});
  s.spheres.push_back(Sphere{glm::vec3(1, 0, 0.5f), 0.5f, mirror});
  expect_all_finite(s, [](Rng& g) {
    Ray r;  // rays nearly parallel to the floor, and tangent to the spheres
    r.o = glm::vec3(-3.0f, g.next_float() - 0.5f, 1e-6f + g.next_float() * 1e-3f);
    r.d = glm::normalize(glm::vec3(1.0f, 0.0f, -1e-4f * g.next_float()));
    if (g.next_float() < 0.5f) r.o.z = 0.5f + (g.next_float() < 0.5f ? 0.5f : -0.5f);
    return r;
  });
}

TEST(bounces, no_nan_with_degenerate_shading_normals) {
  Scene s = floor_scene();
  s.normals = {glm::vec3(0.0f), glm::vec3(NAN), glm::vec3(0, 0, -1), glm::vec3(1e-30f),
               glm::vec3(0.0f), glm::vec3(0, 0, -1)};
  s.lights.push_back(test::ambient_light(glm::vec3(1.0f)));
  Light p;
  p.kind = LightKind::point;
  p.position = glm::vec3(0, 0, 1);
  s.lights.push_back(p);
  expect_all_finite(s, ray_at_floor);
}

// A path that reaches an emitter panel (CGL's emission material: a black BSDF, which has no
// direction to sample, density zero) ends there: no division by that density.
TEST(bounces, no_nan_where_paths_meet_an_emitter_panel) {
  expect_all_finite(test::disagreeing_panel_scene(), [](Rng& g) {
    Ray r;  // from between floor and panel, in every direction: at the floor, the panel, or out
    r.o = glm::vec3(0.0f, 0.0f, 0.5f * test::DisagreeingPanel::kHeight);
    const float z = 2.0f * g.next_float() - 1.0f, phi = 2.0f * float(M_PI) * g.next_float();
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    r.d = glm::vec3(s * std::cos(phi), s * std::sin(phi), z);
    return r;
  });
}

// The hit itself may carry a broken normal (a loader's zero normal, a NaN from a degenerate
// triangle): the shading point falls back to a usable frame and the estimate stays finite.
TEST(bounces, shading_point_repairs_broken_normals) {
  Scene s = floor_scene();
  s.lights.push_back(test::ambient_light(glm::vec3(1.0f)));
  test::Rig rig(s);
  rig.ctx.max_depth = 3;
  rig.ctx.russian_roulette = false;
  Ray ray;
  ray.o = glm::vec3(0, 0, 1);
  {
    // The same hit with sound normals is lit by the sky (a finite zero alone proves nothing):
    // 16 light samples, half of them from above the floor (the sky is sampled over the sphere).
    SurfaceHit hit;
    ASSERT_TRUE(rig.query.intersect(ray, &hit));
    Rng rng(1);
    rig.ctx.light_samples = 16;
    EXPECT_GT(at_least_one_bounce_radiance(rig.ctx, ShadingPoint(s, ray, hit), 1, rng).x, 0.0f)
        << "a floor under a sky, its normals sound: no light came back";
    rig.ctx.light_samples = 1;
  }
  for (glm::vec3 n : {glm::vec3(0.0f), glm::vec3(NAN), glm::vec3(INFINITY, 0, 0)}) {
    for (glm::vec3 ng : {glm::vec3(0, 0, 1), glm::vec3(0.0f), glm::vec3(NAN)}) {
      SurfaceHit hit;
      hit.p = glm::vec3(0.0f);
      hit.n = n;
      hit.ng = ng;
      hit.material = 0;
      ShadingPoint sp(s, ray, hit);
      for (int c = 0; c < 3; ++c) {
        ASSERT_TRUE(std::isfinite(sp.wo[c]) && std::isfinite(sp.frame.n[c]));
        ASSERT_TRUE(std::isfinite(sp.frame.s[c]) && std::isfinite(sp.frame.t[c]));
      }
      Rng rng(1);
      glm::vec3 L = at_least_one_bounce_radiance(rig.ctx, sp, 1, rng);
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(L[c]));
    }
  }
}

// rng is the estimate's only source of random numbers: inside a glowing enclosure every bounce
// meets a wall and each vertex's light depends on where it is, so the answer depends on every
// direction drawn, by light and by hemisphere sampling (roulette, step 3's, off).
TEST(bounces, draws_from_rng_only) {
  test::Rig rig(test::enclosure(0.5f, 1.0f));
  rig.ctx.max_depth = 3;
  rig.ctx.russian_roulette = false;
  for (bool hemisphere : {false, true}) {
    SCOPED_TRACE(hemisphere ? "ctx.hemisphere = true" : "ctx.hemisphere = false");
    rig.ctx.hemisphere = hemisphere;
    Rng g(5);
    const Ray r = test::ray_from_inside(g);
    test::expect_draws_from_rng_only("at_least_one_bounce_radiance", [&](Rng& rng) {
      return test::bounced_at_hit(rig.ctx, r, rng);
    });
  }
}

}  // namespace
}  // namespace pt
