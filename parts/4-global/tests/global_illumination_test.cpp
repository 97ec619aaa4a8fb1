// Part 4: paths of many bounces against scenes whose answer is known at every depth, Russian
// roulette's unbiasedness, bounce selection, MIS, specular spheres, and never a NaN.
#include <gtest/gtest.h>

#include <cmath>

#include "3-direct/tests/lighting_harness.h"
#include "4-global/global_illumination.h"
#include "4-global/integrator.h"

namespace pt {
namespace {

constexpr double kAlpha = 0.001;  // significance of each known-answer t-test

test::Estimator gi(const LightingContext& ctx) {
  return [&ctx](const Ray& r, Rng& g) { return estimate_global_illumination(ctx, r, g); };
}

Scene enclosure(float rho, float E) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(rho), glm::vec3(E));
  test::add_closed_cube(s, m);
  return s;
}

void expect_mean(const std::vector<double>& xs, double expected, const std::string& what) {
  auto c = test::t_test_mean(xs, expected, kAlpha);
  EXPECT_TRUE(c.pass) << what << ": mean " << c.mean << " ± " << c.stderr_ << ", expected "
                      << expected;
}

// Convex: the sphere never sees itself, so every depth gives ρL.
TEST(Part4Global, SphereUnderUniformSkyIsRhoTimesLAtEveryDepth) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.6f));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  s.lights.push_back(test::ambient_light(glm::vec3(2.0f)));
  test::Rig rig(s);
  for (int depth = 1; depth <= 5; ++depth) {
    rig.ctx.max_depth = depth;
    expect_mean(test::sample_values(gi(rig.ctx), test::ray_at_unit_sphere, 10000, depth), 1.2,
                "depth " + std::to_string(depth));
  }
}

// Inside a closed box of albedo ρ emitting E everywhere: E(1 − ρ^(m+1))/(1 − ρ) at depth m
// without Russian roulette, and only the m-th bounce gives ρ^m E.
TEST(Part4Global, EnclosureAtDepthMWithoutRussianRoulette) {
  const double rho = 0.5, E = 1.0;
  test::Rig rig(enclosure(float(rho), float(E)));
  rig.ctx.russian_roulette = false;
  for (int m = 0; m <= 4; ++m) {
    rig.ctx.max_depth = m;
    expect_mean(test::sample_values(gi(rig.ctx), test::ray_from_inside, 4000, 10 + m),
                E * (1 - std::pow(rho, m + 1)) / (1 - rho), "depth " + std::to_string(m));
    rig.ctx.only_bounce = m;
    rig.ctx.max_depth = 4;
    expect_mean(test::sample_values(gi(rig.ctx), test::ray_from_inside, 4000, 20 + m),
                E * std::pow(rho, m), "only bounce " + std::to_string(m));
    rig.ctx.only_bounce = -1;
  }
}

TEST(Part4Global, EnclosureConvergesToEOverOneMinusRhoWithRussianRoulette) {
  const double rho = 0.5, E = 1.0;
  test::Rig rig(enclosure(float(rho), float(E)));
  rig.ctx.max_depth = 1000;
  rig.ctx.russian_roulette = true;
  expect_mean(test::sample_values(gi(rig.ctx), test::ray_from_inside, 20000, 3), E / (1 - rho),
              "Russian roulette, depth 1000");
  rig.ctx.mis = true;
  expect_mean(test::sample_values(gi(rig.ctx), test::ray_from_inside, 20000, 4), E / (1 - rho),
              "MIS, Russian roulette, depth 1000");
  rig.ctx.mis = false;
  rig.ctx.hemisphere = true;
  expect_mean(test::sample_values(gi(rig.ctx), test::ray_from_inside, 20000, 5), E / (1 - rho),
              "hemisphere sampling, Russian roulette, depth 1000");
}

// The design's known answer: a point light of intensity π at the centre of a unit sphere of
// albedo 0.5, seen from inside, has radiance 1 (0.5 direct, doubled by interreflection).
TEST(Part4Global, PointLightInsideADiffuseSphereGivesRadianceOne) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  Light l;
  l.kind = LightKind::point;
  l.radiance = glm::vec3(float(M_PI));
  s.lights.push_back(l);
  test::Rig rig(s);
  rig.ctx.max_depth = 1000;
  expect_mean(test::sample_values(gi(rig.ctx), test::ray_from_inside, 20000, 8), 1.0,
              "point light in a sphere");
}

// A lossless glass sphere or a mirror of reflectance R in a uniform sky: L and RL.
TEST(Part4Global, SpecularSpheresUnderUniformSky) {
  for (MaterialKind kind : {MaterialKind::glass, MaterialKind::mirror}) {
    Scene s;
    uint32_t m = test::add_material(s, glm::vec3(0.0f), glm::vec3(0.0f), kind);
    s.materials[m].reflectance = glm::vec3(kind == MaterialKind::mirror ? 0.8f : 1.0f);
    s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
    s.lights.push_back(test::ambient_light(glm::vec3(1.0f)));
    test::Rig rig(s);
    rig.ctx.max_depth = 100;
    expect_mean(test::sample_values(gi(rig.ctx), test::ray_at_unit_sphere, 10000, 9),
                kind == MaterialKind::mirror ? 0.8 : 1.0, to_string(kind));
  }
}

// CBcoil's panel and light disagree (test::disagreeing_panel_scene): MIS's BSDF samples reach the
// panel and its light samples the same panel, with the light's radiance, so MIS lights the floor
// as light sampling does: ρ·L·F over the panel's rectangle.
TEST(Part4Global, MisSeesThePanelsShapeWithItsLightsRadiance) {
  using P = test::DisagreeingPanel;
  test::Rig rig(test::disagreeing_panel_scene());
  rig.ctx.mis = true;
  rig.ctx.light_samples = 4;
  rig.ctx.max_depth = 1;
  auto floor_point = [](Rng&) {
    Ray r;
    r.o = glm::vec3(0.4f, 0.0f, 0.2f);
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    return r;
  };
  expect_mean(test::sample_values(gi(rig.ctx), floor_point, 10000, 12), P::floor_radiance(0.4, 0.0),
              "MIS, direct light on the floor");
}

// The same room with a mirror floor: the camera sees the panel in the mirror with the radiance
// light sampling gives it, the light's (5, not the panel's 10), by every estimator.
TEST(Part4Global, AMirrorShowsThePanelWithItsLightsRadiance) {
  using P = test::DisagreeingPanel;
  for (int mode = 0; mode < 3; ++mode) {
    test::Rig rig(test::disagreeing_panel_scene(MaterialKind::mirror));
    rig.ctx.hemisphere = mode == 1;
    rig.ctx.mis = mode == 2;
    rig.ctx.max_depth = 1;
    Ray r;
    r.o = glm::vec3(0.1f, 0.05f, 0.2f);
    r.d = glm::normalize(glm::vec3(0.05f, 0.02f, -1.0f));
    Rng rng(3);
    const glm::vec3 L = estimate_global_illumination(rig.ctx, r, rng);
    EXPECT_NEAR(L.x, P::kLightRadiance, 1e-4f) << "mode " << mode;
  }
}

TEST(Part4Global, DepthOneSamplesNoBounce) {
  test::Rig rig(enclosure(0.5f, 1.0f));
  rig.ctx.max_depth = 1;
  Rng rng(1);
  Ray r;
  estimate_global_illumination(rig.ctx, r, rng);
  EXPECT_EQ(rig.query.intersect_calls, 1) << "only the camera ray is traced";
  EXPECT_EQ(rig.query.occluded_calls, rig.ctx.light_samples) << "and the light's shadow rays";
}

TEST(Part4Global, NoLightsAndNoEmittersShowNormalsWithoutShadowRays) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m);
  test::DoubleQuery query(s);
  RenderSettings settings;
  settings.max_depth = 5;
  std::string error;
  auto integrator = Integrator::create(settings, s, query, &error);
  ASSERT_TRUE(integrator) << error;
  EXPECT_TRUE(integrator->shows_normals());
  Ray r;
  r.o = glm::vec3(0, 0, 1);
  Rng rng(1);
  glm::vec3 L = integrator->radiance(r, rng);
  EXPECT_NEAR(L.z, 1.0f, 1e-6f);  // normal (0, 0, 1) shown as (0.5, 0.5, 1)
  EXPECT_EQ(query.occluded_calls, 0);
}

}  // namespace
}  // namespace pt
