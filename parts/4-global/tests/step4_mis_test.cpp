// Part 4, step 4 (mis): the power heuristic on hand-computed cases, and direct light by light and
// BSDF samples weighted by it is unbiased. estimate_direct_mis is called itself, at a hit the
// rig found, shaded with the rig's Lambertian: no path (steps 1-3) and no student BSDF in it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "framework/testing/draws_from_rng_only.h"
#include "parts/4-global/mis.h"
#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

TEST(mis, power_heuristic_on_hand_computed_cases) {
  EXPECT_FLOAT_EQ(power_heuristic(1, 1.0f, 1, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(power_heuristic(2, 1.0f, 1, 1.0f), 0.8f);    // (2·1)² / ((2·1)² + 1²)
  EXPECT_FLOAT_EQ(power_heuristic(1, 2.0f, 4, 1.0f), 0.2f);    // 2² / (2² + 4²)
  EXPECT_FLOAT_EQ(power_heuristic(1, 2.0f, 1, 0.0f), 1.0f);    // only strategy a draws it
  EXPECT_FLOAT_EQ(power_heuristic(1, 0.0f, 1, 2.0f), 0.0f);
  EXPECT_FLOAT_EQ(power_heuristic(1, 0.0f, 1, 0.0f), 0.0f) << "no strategy draws it: no NaN";
  EXPECT_FLOAT_EQ(power_heuristic(1, std::numeric_limits<float>::infinity(), 1, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(power_heuristic(1, 1e30f, 1, 1.0f), 1.0f) << "a² overflows: still 1, no NaN";
  // The weights of the two strategies for one sample add up to 1.
  EXPECT_FLOAT_EQ(power_heuristic(3, 0.7f, 2, 1.9f) + power_heuristic(2, 1.9f, 3, 0.7f), 1.0f);
}

/// Direct light by MIS at the first hit of `ray`, for sample_values.
test::Estimator mis_at_hit(const test::Rig& rig) {
  return [&rig](const Ray& ray, Rng& rng) {
    SurfaceHit hit;
    if (!rig.query.intersect(ray, &hit)) return glm::vec3(0.0f);
    const test::RigPoint p(rig.ctx.scene, ray, hit);
    return estimate_direct_mis(rig.ctx, p.point, rng);
  };
}

const char* const kMisBias =
    ": do a direction's weights over the two strategies sum to one (power_heuristic with each "
    "strategy's count and density), and is each strategy's sum divided by its own count?";

// Inside a closed box of albedo ρ glowing E everywhere, the direct light at a wall is ρE.
TEST(mis, direct_light_in_a_glowing_enclosure_is_rho_times_e) {
  const double rho = 0.5, E = 1.0;
  test::Rig rig(test::enclosure(float(rho), float(E)));
  for (int l : {1, 3}) {
    rig.ctx.light_samples = l;
    auto c = test::t_test_mean(
        test::sample_values(mis_at_hit(rig), test::ray_from_inside, 10000, 4 + l), rho * E,
        test::kPathAlpha);
    EXPECT_TRUE(c.pass) << "MIS, -l " << l << ": mean " << c.mean << " ± " << c.stderr_
                        << ", expected ρE = " << rho * E << kMisBias;
  }
}

// CBcoil's panel and light disagree (test::disagreeing_panel_scene): MIS's BSDF samples receive
// the light where they cross its rectangle, which its light samples sample, so MIS lights the
// floor as light sampling does: ρ·L·F over the light's rectangle, not the panel's.
TEST(mis, floor_is_lit_by_the_lights_rectangle) {
  using P = test::DisagreeingPanel;
  test::Rig rig(test::disagreeing_panel_scene());
  rig.ctx.light_samples = 4;
  auto floor_point = [](Rng&) {
    Ray r;
    r.o = glm::vec3(0.4f, 0.0f, 0.2f);
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    return r;
  };
  auto c = test::t_test_mean(test::sample_values(mis_at_hit(rig), floor_point, 10000, 12),
                             P::floor_radiance(0.4, 0.0), test::kPathAlpha);
  EXPECT_TRUE(c.pass) << "MIS, direct light on the floor: mean " << c.mean << " ± " << c.stderr_
                      << ", expected " << P::floor_radiance(0.4, 0.0) << kMisBias;
}

// No light or BSDF sample counts at a mirror: zero, and nothing traced to find that out; the
// diffuse floor of the same room is lit (a zero alone proves nothing).
TEST(mis, a_mirror_gets_no_direct_light) {
  Ray r;
  r.o = glm::vec3(0.1f, 0.05f, 0.2f);
  r.d = glm::vec3(0.0f, 0.0f, -1.0f);
  for (MaterialKind kind : {MaterialKind::mirror, MaterialKind::diffuse}) {
    test::Rig rig(test::disagreeing_panel_scene(kind));
    rig.ctx.light_samples = 4;
    SurfaceHit hit;
    ASSERT_TRUE(rig.query.intersect(r, &hit));
    const test::RigPoint p(rig.ctx.scene, r, hit);
    rig.query.intersect_calls = rig.query.occluded_calls = 0;
    Rng rng(2);
    const glm::vec3 L = estimate_direct_mis(rig.ctx, p.point, rng);
    if (kind == MaterialKind::mirror) {
      EXPECT_EQ(L, glm::vec3(0.0f)) << "a mirror: no light sample can reach its one direction";
      EXPECT_EQ(rig.query.intersect_calls + rig.query.occluded_calls, 0)
          << "a mirror (is_delta()): nothing to trace";
    } else {
      EXPECT_GT(L.x, 0.0f) << "the diffuse floor under the panel got no direct light by MIS";
    }
  }
}

// MIS takes both kinds of sample: -l light samples per light and -l BSDF samples, one ray each
// (a floor under one area light with a panel: every sample of either kind is usable). Part 3's
// light sampling alone traces half as many.
TEST(mis, takes_l_light_samples_and_l_bsdf_samples) {
  Scene s;
  const uint32_t white = test::add_material(s, glm::vec3(0.5f));
  const uint32_t glow = test::add_material(s, glm::vec3(0.0f), glm::vec3(5.0f));
  test::add_square_ceiling_light(s, 0.5f, 0.99f, glm::vec3(5.0f), glow);  // panel, facing down
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, white);  // the floor
  for (int l : {1, 4}) {
    SCOPED_TRACE("-l " + std::to_string(l));
    test::Rig rig(s);
    rig.ctx.light_samples = l;
    Ray r;
    r.o = glm::vec3(0.1f, 0.2f, 0.5f);
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    SurfaceHit hit;
    ASSERT_TRUE(rig.query.intersect(r, &hit));
    const test::RigPoint p(rig.ctx.scene, r, hit);
    rig.query.intersect_calls = rig.query.occluded_calls = 0;
    Rng rng(6);
    EXPECT_GT(estimate_direct_mis(rig.ctx, p.point, rng).x, 0.0f);
    EXPECT_EQ(rig.query.intersect_calls + rig.query.occluded_calls, 2 * l)
        << "rays traced for one floor point under one area light: -l light samples (one shadow "
           "ray each) and -l BSDF samples (one ray each); light sampling alone traces -l";
  }
}

// A point light is a light no ray can hit: its one sample keeps weight 1, since no BSDF sample
// could have drawn it, and MIS gives exactly what light sampling gives for it, the irradiance law
// ρ/π · I cosθ / d², with -l 1 and -l 4 (the BSDF samples find nothing).
TEST(mis, a_light_no_ray_can_hit_keeps_weight_one) {
  Scene s;
  const uint32_t m = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  Light l;
  l.kind = LightKind::point;
  l.position = glm::vec3(1.0f, 0.0f, 2.0f);
  l.radiance = glm::vec3(10.0f);
  s.lights.push_back(l);
  test::Rig rig(s);
  const double d2 = 1.0 + 4.0, cos_theta = 2.0 / std::sqrt(d2);
  const double expected = 0.5 / M_PI * 10.0 * cos_theta / d2;
  Ray r;
  r.o = glm::vec3(0.0f, 0.0f, 3.0f);
  r.d = glm::vec3(0.0f, 0.0f, -1.0f);
  for (int n : {1, 4}) {
    rig.ctx.light_samples = n;
    Rng rng(3);
    const glm::vec3 L = mis_at_hit(rig)(r, rng);
    EXPECT_NEAR(L.x, expected, 1e-5 * expected)
        << "-l " << n << ": a point light's sample under MIS gave " << L.x << " where light "
        << "sampling gives " << expected << test::ratio_hint(L.x, expected, {})
        << " (no BSDF sample can reach a point light, so its sample keeps weight 1: weigh only "
           "the samples of a light ctx.lights says can_be_hit)";
  }
}

// rng is the estimate's only source of random numbers: on the floor under the light both
// strategies' samples bring light, each its own, so the answer depends on every number drawn.
TEST(mis, draws_from_rng_only) {
  test::Rig rig(test::disagreeing_panel_scene());
  rig.ctx.light_samples = 4;
  Ray r;
  r.o = glm::vec3(0.4f, 0.0f, 0.2f);
  r.d = glm::vec3(0.0f, 0.0f, -1.0f);
  const test::Estimator mis = mis_at_hit(rig);
  test::expect_draws_from_rng_only("estimate_direct_mis", [&](Rng& rng) { return mis(r, rng); });
}

}  // namespace
}  // namespace pt
