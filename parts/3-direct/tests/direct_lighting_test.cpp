// Part 3: zero-bounce and direct light against scenes whose answer is known, the two direct
// estimators against each other, and the work each one skips when the scene does not need it.
#include <gtest/gtest.h>

#include <cmath>

#include "3-direct/direct_lighting.h"
#include "3-direct/tests/lighting_harness.h"
#include "render/pixel_stats.h"
#include "scene/collada_loader.h"
#include "stats/block_ttest.h"

namespace pt {
namespace {

constexpr double kAlpha = 0.001;  // significance of each known-answer t-test

// Direct light only (Part 3's estimators, without Part 4): emission plus one_bounce_radiance.
glm::vec3 direct_only(const LightingContext& ctx, const Ray& ray, Rng& rng) {
  SurfaceHit hit;
  if (!ctx.query.intersect(ray, &hit)) return ctx.lights.environment_radiance(ray.d);
  ShadingPoint sp(ctx.scene, ray, hit);
  return zero_bounce_radiance(ctx, ray, hit) + one_bounce_radiance(ctx, sp, rng);
}

Scene sphere_under_sky(float rho, float L) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(rho));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  s.lights.push_back(test::ambient_light(glm::vec3(L)));
  return s;
}

TEST(Part3Direct, ZeroBounceIsTheEmissionSeen) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f), glm::vec3(2.0f, 3.0f, 4.0f));
  test::add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m);
  test::Rig rig(s);
  Ray r;
  r.o = glm::vec3(0.1f, 0.2f, 1.0f);
  SurfaceHit hit;
  ASSERT_TRUE(rig.query.intersect(r, &hit));
  glm::vec3 L = zero_bounce_radiance(rig.ctx, r, hit);
  EXPECT_EQ(L, glm::vec3(2.0f, 3.0f, 4.0f));
}

// An area light's panel hangs just under a ceiling, facing down (as in the course's Cornell
// boxes). The light shines down only, so its panel must glow on that side only: seen from
// above, and for the ceiling over it, whichever estimator is used.
Scene panel_under_ceiling() {
  Scene s;
  const uint32_t white = test::add_material(s, glm::vec3(0.5f));
  const uint32_t glow = test::add_material(s, glm::vec3(0.0f), glm::vec3(5.0f));
  test::add_quad(s, {-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}, white);  // ceiling
  test::add_quad(s, {-0.5f, -0.5f, 0.99f}, {0.5f, -0.5f, 0.99f}, {0.5f, 0.5f, 0.99f},
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

TEST(Part3Direct, AreaLightPanelGlowsOnItsLightsSideOnly) {
  test::Rig rig(panel_under_ceiling());
  Ray up;
  up.o = glm::vec3(0.1f, 0.2f, 0.0f);
  up.d = glm::vec3(0.0f, 0.0f, 1.0f);
  SurfaceHit hit;
  ASSERT_TRUE(rig.query.intersect(up, &hit));
  EXPECT_EQ(zero_bounce_radiance(rig.ctx, up, hit), glm::vec3(5.0f)) << "seen from below";
  Ray down;
  down.o = glm::vec3(0.1f, 0.2f, 0.995f);
  down.d = glm::vec3(0.0f, 0.0f, -1.0f);
  ASSERT_TRUE(rig.query.intersect(down, &hit));
  ASSERT_NEAR(hit.t, 0.005f, 1e-5f) << "the ray should meet the panel's back";
  EXPECT_EQ(zero_bounce_radiance(rig.ctx, down, hit), glm::vec3(0.0f)) << "seen from above";
}

TEST(Part3Direct, CeilingOverAPanelIsDarkByBothEstimators) {
  // Most hemisphere directions from the ceiling's point meet the panel's back 1 cm below: they
  // must bring nothing, exactly as light sampling (which sees the light from behind) says.
  for (bool hemisphere : {true, false}) {
    test::Rig rig(panel_under_ceiling());
    rig.ctx.hemisphere = hemisphere;
    rig.ctx.light_samples = 64;
    Ray up;
    up.o = glm::vec3(0.1f, 0.2f, 0.995f);
    up.d = glm::vec3(0.0f, 0.0f, 1.0f);
    SurfaceHit hit;
    ASSERT_TRUE(rig.query.intersect(up, &hit));
    ShadingPoint sp(rig.ctx.scene, up, hit);
    Rng rng(5);
    glm::vec3 sum(0.0f);
    for (int i = 0; i < 64; ++i) sum += one_bounce_radiance(rig.ctx, sp, rng);
    EXPECT_EQ(sum, glm::vec3(0.0f)) << (hemisphere ? "hemisphere" : "light importance");
  }
}

// A closed box whose six faces are one CGL emitter (radiance E) with a phong diffuse colour a, as
// Blender writes the course's light panels. The course reads such a material as emission only:
// every ray inside sees exactly E. Were the panels to reflect their diffuse colour as well, the
// irradiance πE inside the uniform enclosure would add a·E to every direct-light estimate
// (E/(1 − a) over all bounces).
constexpr char kEmitterBox[] = R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_effects><effect id="glow-fx"><profile_COMMON><technique sid="common"><phong>
    <emission><color>0 0 0 1</color></emission><diffuse><color>0.8 0.8 0.8 1</color></diffuse>
  </phong></technique></profile_COMMON>
  <extra><technique profile="CGL"><emission><radiance>2 2 2</radiance></emission></technique></extra>
  </effect></library_effects>
  <library_materials><material id="glow" name="glow"><instance_effect url="#glow-fx"/></material></library_materials>
  <library_geometries><geometry id="box"><mesh>
    <source id="box-p"><float_array id="box-pa" count="24">-1 -1 -1 1 -1 -1 -1 1 -1 1 1 -1 -1 -1 1 1 -1 1 -1 1 1 1 1 1</float_array>
      <technique_common><accessor source="#box-pa" count="8" stride="3"/></technique_common></source>
    <vertices id="box-v"><input semantic="POSITION" source="#box-p"/></vertices>
    <polylist material="glow" count="6"><input semantic="VERTEX" source="#box-v" offset="0"/>
      <vcount>4 4 4 4 4 4</vcount><p>0 2 3 1 4 5 7 6 0 1 5 4 2 6 7 3 0 4 6 2 1 3 7 5</p></polylist>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#box">
    <bind_material><technique_common><instance_material symbol="glow" target="#glow"/></technique_common></bind_material>
  </instance_geometry></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>)";

TEST(Part3Direct, EmitterPanelsReflectNothingInAClosedBox) {
  const double E = 2.0, a = 0.8;
  const Scene box = load_collada_string(kEmitterBox, "emitter_box.dae", [](const std::string&) {});
  ASSERT_EQ(box.triangles.size(), 12u);
  for (bool hemisphere : {false, true}) {
    test::Rig rig(box);
    rig.ctx.hemisphere = hemisphere;
    rig.ctx.light_samples = 4;
    auto xs = test::sample_values([&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
                                  test::ray_from_inside, 4000, 3);
    auto c = test::t_test_mean(xs, E, kAlpha);
    EXPECT_TRUE(c.pass) << (hemisphere ? "hemisphere" : "importance") << ": mean " << c.mean
                        << " ± " << c.stderr_ << ", expected E = " << E
                        << " (E(1 + a) = " << E * (1 + a) << " if the panels reflected)";
  }
  // The known amount the panels' reflection would add, seen by the same harness: the box drawn
  // with its diffuse colour (the reading this replaces) gives E(1 + a).
  Scene reflecting = box;
  for (Material& m : reflecting.materials) m.kind = MaterialKind::diffuse;
  test::Rig rig(reflecting);
  rig.ctx.light_samples = 4;
  auto xs = test::sample_values([&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
                                test::ray_from_inside, 4000, 4);
  auto c = test::t_test_mean(xs, E * (1 + a), kAlpha);
  EXPECT_TRUE(c.pass) << "reflecting panels: mean " << c.mean << " ± " << c.stderr_
                      << ", expected E(1 + a) = " << E * (1 + a);
}

// CBcoil's panel and light disagree (test::disagreeing_panel_scene). The camera sees the panel's
// shape glowing with the light's radiance, from below only; where the light reaches beyond the
// panel there is nothing to see.
TEST(Part3Direct, TheCameraSeesThePanelsShapeWithItsLightsRadiance) {
  using P = test::DisagreeingPanel;
  test::Rig rig(test::disagreeing_panel_scene());
  auto look = [&](float x, float y, float z, float dz, SurfaceHit* hit) {
    Ray r;
    r.o = glm::vec3(x, y, z);
    r.d = glm::vec3(0.0f, 0.0f, dz);
    return rig.query.intersect(r, hit) ? zero_bounce_radiance(rig.ctx, r, *hit) : glm::vec3(-1.0f);
  };
  SurfaceHit hit;
  EXPECT_EQ(look(0.1f, 0.1f, 0.2f, 1.0f, &hit), glm::vec3(P::kLightRadiance)) << "the panel from below";
  EXPECT_EQ(look(0.35f, 0.0f, 0.2f, 1.0f, &hit), glm::vec3(P::kLightRadiance))
      << "the panel where the light does not reach";
  EXPECT_EQ(look(0.0f, 0.35f, 0.2f, 1.0f, &hit), glm::vec3(-1.0f))
      << "where only the light reaches, nothing is there to be seen";
  EXPECT_EQ(look(0.1f, 0.1f, 0.7f, -1.0f, &hit), glm::vec3(0.0f)) << "the panel from above";
}

// The floor beside the panel, lit by it: ρ·L·F with the light's radiance over the panel's
// rectangle (F by the corner formula), whichever estimator (light sampling of the light's own
// rectangle would give 13% less, hemisphere sampling of the panel's emission twice as much).
TEST(Part3Direct, EveryEstimatorSeesThePanelsShapeWithItsLightsRadiance) {
  using P = test::DisagreeingPanel;
  const double expected = P::floor_radiance(0.4, 0.0);
  for (bool hemisphere : {false, true}) {
    test::Rig rig(test::disagreeing_panel_scene());
    rig.ctx.hemisphere = hemisphere;
    rig.ctx.light_samples = 4;
    auto xs = test::sample_values(
        [&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
        [](Rng&) {
          Ray r;
          r.o = glm::vec3(0.4f, 0.0f, 0.2f);
          r.d = glm::vec3(0.0f, 0.0f, -1.0f);
          return r;
        },
        hemisphere ? 40000 : 10000, 9);
    auto c = test::t_test_mean(xs, expected, kAlpha);
    EXPECT_TRUE(c.pass) << (hemisphere ? "hemisphere" : "importance") << ": mean " << c.mean
                        << " ± " << c.stderr_ << ", expected " << expected;
  }
}

// A convex diffuse sphere of albedo ρ under a uniform sky L never sees itself: L_out = ρL.
void check_sphere_under_sky(bool hemisphere) {
  const float rho = 0.6f, L = 2.0f;
  test::Rig rig(sphere_under_sky(rho, L));
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.light_samples = 4;
  auto xs = test::sample_values([&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
                                test::ray_at_unit_sphere, 20000, 11);
  auto c = test::t_test_mean(xs, rho * L, kAlpha);
  EXPECT_TRUE(c.pass) << "mean " << c.mean << " ± " << c.stderr_ << ", expected " << rho * L;
}
TEST(Part3Direct, SphereUnderUniformSkyIsRhoTimesLByImportance) { check_sphere_under_sky(false); }
TEST(Part3Direct, SphereUnderUniformSkyIsRhoTimesLByHemisphere) { check_sphere_under_sky(true); }

// A diffuse plane facing a uniform sky, seen from above: ρL as well (it sees only sky).
TEST(Part3Direct, PlaneUnderUniformSkyIsRhoTimesL) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.3f));
  test::add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  s.lights.push_back(test::ambient_light(glm::vec3(1.5f)));
  for (bool hemisphere : {false, true}) {
    test::Rig rig(s);
    rig.ctx.hemisphere = hemisphere;
    auto xs = test::sample_values(
        [&](const Ray& r, Rng& g) { return direct_only(rig.ctx, r, g); },
        [](Rng& g) {
          Ray r;
          r.o = glm::vec3(g.next_float() - 0.5f, g.next_float() - 0.5f, 1.0f);
          r.d = glm::normalize(glm::vec3(0.1f, -0.2f, -1.0f));
          return r;
        },
        20000, 5);
    auto c = test::t_test_mean(xs, 0.3 * 1.5, kAlpha);
    EXPECT_TRUE(c.pass) << (hemisphere ? "hemisphere" : "importance") << ": mean " << c.mean
                        << " ± " << c.stderr_ << ", expected 0.45";
  }
}

// One point light over a plane: the estimate is exact, ρ/π · I cosθ / d².
TEST(Part3Direct, PointLightOverPlaneIsExact) {
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
  glm::vec3 L = direct_only(rig.ctx, r, rng);
  const double d2 = 1.0 + 4.0, cos_theta = 2.0 / std::sqrt(d2);
  const double expected = 0.5 / M_PI * 10.0 * cos_theta / d2;
  EXPECT_NEAR(L.x, expected, 1e-5 * expected);
  // A delta light takes one sample whatever -l says: one shadow ray.
  EXPECT_EQ(rig.query.occluded_calls, 1);
}

// A small Cornell-like box lit by its emissive ceiling, rendered at 16×16 by a pinhole.
Scene lit_box() {
  Scene s;
  uint32_t white = test::add_material(s, glm::vec3(0.7f));
  uint32_t red = test::add_material(s, glm::vec3(0.7f, 0.1f, 0.1f));
  uint32_t lamp = test::add_material(s, glm::vec3(0.0f), glm::vec3(3.0f));
  test::add_quad(s, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, white);  // floor
  test::add_quad(s, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, white);  // back
  test::add_quad(s, {-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, red);    // left
  test::add_quad(s, {-0.9f, 0.99f, -0.9f}, {0.9f, 0.99f, -0.9f}, {0.9f, 0.99f, 0.9f},
                 {-0.9f, 0.99f, 0.9f}, lamp);
  test::add_triangle(s, {-0.3f, -1, 0.2f}, {0.5f, -1, -0.3f}, {0.1f, 0.2f, 0.0f}, white);
  return s;
}

RenderEstimate render_box(const Scene& scene, bool hemisphere, int spp, float scale,
                          uint64_t seed) {
  test::Rig rig(scene);
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.light_samples = 4;
  const int W = 16, H = 16;
  RenderEstimate e;
  e.width = W;
  e.height = H;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      Rng rng(seed, uint64_t(y * W + x));
      PixelStats st;
      for (int i = 0; i < spp; ++i) {
        glm::vec2 j = rng.next_2d();
        Ray r;
        r.o = glm::vec3(0.0f, 0.0f, 3.5f);
        r.d = glm::normalize(glm::vec3((x + j.x) / W - 0.5f, 0.5f - (y + j.y) / H, -1.2f));
        st.add(scale * direct_only(rig.ctx, r, rng));
      }
      e.mean.push_back(glm::vec3(st.mean));
      e.variance.push_back(glm::vec3(st.variance()));
      e.count.push_back(float(st.count));
    }
  return e;
}

// The two direct estimators estimate the same integral: the block t-test (family-wise 0.01)
// finds no difference, and does find a 5% bias.
TEST(Part3Direct, HemisphereAndImportanceSamplingConvergeToTheSameImage) {
  Scene s = lit_box();
  RenderEstimate importance = render_box(s, false, 256, 1.0f, 1);
  RenderEstimate hemisphere = render_box(s, true, 2048, 1.0f, 2);
  BlockTestOptions opt;
  opt.block_size = 4;
  opt.alpha = 0.01;
  BlockTestResult same = block_t_test(importance, hemisphere, opt);
  EXPECT_TRUE(same.pass) << same.summary;
  RenderEstimate biased = render_box(s, false, 256, 0.95f, 3);
  BlockTestResult differ = block_t_test(biased, hemisphere, opt);
  EXPECT_FALSE(differ.pass) << "a 5% darker image was not detected: " << differ.summary;
}

// What the scene does not need is not done.
TEST(Part3Direct, NoEnvironmentMeansAMissIsBlackAtOnce) {
  Scene s;
  Light l;
  l.kind = LightKind::point;
  s.lights.push_back(l);
  test::Rig rig(s);
  Rng rng(1);
  Ray r;
  EXPECT_EQ(direct_only(rig.ctx, r, rng), glm::vec3(0.0f));
  EXPECT_EQ(rig.query.intersect_calls, 1);
  EXPECT_EQ(rig.query.occluded_calls, 0);
}

TEST(Part3Direct, ABlackSurfaceTracesNoShadowRays) {
  Scene s = sphere_under_sky(0.0f, 1.0f);
  test::Rig rig(s);
  rig.ctx.light_samples = 8;
  Rng rng(1);
  Ray r;
  r.o = glm::vec3(0, 0, 3);
  EXPECT_EQ(direct_only(rig.ctx, r, rng), glm::vec3(0.0f));
  EXPECT_EQ(rig.query.occluded_calls, 0);
}

}  // namespace
}  // namespace pt
