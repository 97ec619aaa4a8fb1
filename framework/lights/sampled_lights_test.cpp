// Not needed for the assignment.
// SampledLights: the samples of each kind of light, as directions from a point, against the density
// SampledLights::pdf claims for them (chi-square at significance 0.01, Nori's level; each density
// integrates to 1); and the emitter rule: an area light with a panel on it lights the scene from
// its own rectangle (light samples land there, hemisphere and BSDF samples reach it there) while
// the camera sees the panel, and a panel that disagrees with its light says so once.
#include "framework/lights/sampled_lights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "framework/math/float_error.h"
#include "framework/sampling/chi2_test_util.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/scene/collada_loader.h"
#include "framework/testing/test_paths.h"
#include "framework/testing/test_scenes.h"

namespace pt {
namespace {

// The light samples of one light as directions from a point, against SampledLights::pdf.
Chi2Result light_chi2(const Scene& scene, const SurfaceHit& at, const glm::vec3& aim,
                      Chi2Options opt = {}) {
  SampledLights lights(scene);
  test::DoubleQuery query(scene);
  return chi2_direction_test(
      [&](glm::vec2 u, glm::vec3* w) {
        LightSample ls = lights.make_sample(0, at, u);
        *w = ls.wi;
        return ls.pdf > 0.0f;
      },
      [&](const glm::vec3& w) {
        Ray r;
        r.o = at.p;
        r.d = w;
        SurfaceHit h;
        if (!query.intersect(r, &h)) return double(lights.pdf(0, at, w, nullptr));
        return double(lights.pdf(0, at, w, &h));
      },
      Frame(glm::normalize(aim)), opt);
}

/// Light 0 of `scene`, sampled from `p`, fits the density pdf() claims (chi-square, in a frame
/// around `aim`); the lights here have straight edges that cut cells, so a fine quadrature keeps
/// their expected share exact.
void expect_light_fits_its_density(const Scene& scene, const glm::vec3& p, const glm::vec3& aim) {
  SurfaceHit at;
  at.p = p;
  Chi2Options opt;
  opt.quadrature = 96;
  const Chi2Result r = light_chi2(scene, at, aim, opt);
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

TEST(FrameworkSampledLights, TriangleLightBySolidAngleFitsItsDensity) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0), glm::vec3(1));
  test::add_triangle(s, {-1, -0.5f, 1}, {1.5f, -0.7f, 1.2f}, {0.2f, 1.0f, 0.6f}, m);
  expect_light_fits_its_density(s, glm::vec3(0.1f, 0.0f, 0.0f), {0.1f, 0.0f, 1.0f});
}

TEST(FrameworkSampledLights, RectangleAreaLightBySolidAngleFitsItsDensity) {
  Scene s;
  Light l;
  l.kind = LightKind::area;
  l.position = glm::vec3(0.0f, 0.0f, 1.0f);
  l.edge_u = glm::vec3(1.6f, 0.0f, 0.0f);
  l.edge_v = glm::vec3(0.3f, 1.2f, 0.0f);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  s.lights.push_back(l);
  expect_light_fits_its_density(s, glm::vec3(0.2f, -0.1f, 0.0f), {0, 0, 1});
}

// An area light with a panel that is not its shape (CBcoil's 0.8 × 0.6 panel on a 0.6 × 0.8
// light): its samples are directions to the light's rectangle, with the density pdf() gives the
// direction.
TEST(FrameworkSampledLights, AreaLightPanelBySolidAngleFitsItsDensity) {
  Scene s = test::disagreeing_panel_scene();
  expect_light_fits_its_density(s, glm::vec3(0.4f, 0.0f, 0.0f), {-0.4f, 0.0f, 0.5f});
}

TEST(FrameworkSampledLights, SphereLightConeFitsItsDensity) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0), glm::vec3(1));
  // Radius sqrt(1.75) at distance 2: the cone's rim is at cosθ = 0.75, an edge of the test's
  // grid, so the midpoint quadrature integrates every cell exactly.
  s.spheres.push_back(Sphere{glm::vec3(0.0f, 0.0f, 2.0f), std::sqrt(1.75f), m});
  SurfaceHit at;
  at.p = glm::vec3(0.0f);
  Chi2Options opt;
  opt.quadrature = 8;
  const Chi2Result r = light_chi2(s, at, {0, 0, 1}, opt);
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

/// A panel of two triangles spanning [-hx, hx] × [-hy, hy] at height z, of emission `emission`,
/// under an area light of full edges `u`, `v` there, shining down with `radiance`.
Scene panel_on_light(float hx, float hy, float emission, const glm::vec3& u, const glm::vec3& v,
                     float radiance, float z = 1.0f) {
  Scene s;
  Material m;
  m.name = "panel";
  m.kind = MaterialKind::emission;
  m.emission = glm::vec3(emission);
  s.materials.push_back(m);
  s.positions = {{-hx, -hy, z}, {hx, -hy, z}, {hx, hy, z}, {-hx, hy, z}};
  s.triangles = {Triangle{{0, 1, 2}, 0}, Triangle{{0, 2, 3}, 0}};
  Light l;
  l.name = "Lamp";
  l.kind = LightKind::area;
  l.radiance = glm::vec3(radiance);
  l.position = glm::vec3(0.0f, 0.0f, z);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  l.edge_u = u;
  l.edge_v = v;
  s.lights.push_back(l);
  return s;
}

SurfaceHit panel_hit(const glm::vec3& p, uint32_t primitive) {
  SurfaceHit h;
  h.p = p;
  h.ng = glm::vec3(0.0f, 0.0f, 1.0f);  // the winding's side: up, away from the light's side
  h.n = h.ng;
  h.primitive = primitive;
  return h;
}

/// The end of a panel or mesh light's sample by its definition in glm: the point wa + wb + wc
/// seen from p, its error bound γ6·(|wa| + |wb| + |wc|), the normal n, the light's 1 / area.
LightSample surface_sample_by_definition(const SampledLight& l, const glm::vec3& p,
                                         const glm::vec3& wa, const glm::vec3& wb,
                                         const glm::vec3& wc, const glm::vec3& n, bool one_sided) {
  const glm::vec3 q = wa + wb + wc;
  const glm::vec3 d = q - p;
  const float dist = glm::length(d);
  if (!(dist > 0.0f) || !std::isfinite(dist)) return {};
  LightSample ls;
  ls.wi = d / dist;
  ls.target.distance = dist;
  ls.target.p = q;
  ls.target.p_error = gamma(6) * (glm::abs(wa) + glm::abs(wb) + glm::abs(wc));
  ls.target.n = n;
  const float cos_l = glm::dot(-ls.wi, n);
  if (one_sided && !(cos_l > 0.0f)) return {};
  ls.pdf = area_to_solid_angle_pdf(1.0f / l.area, dist, cos_l);
  ls.L = ls.pdf > 0.0f ? l.radiance : glm::vec3(0.0f);
  return ls;
}

void expect_same_bits(const glm::vec3& a, const glm::vec3& b, const char* what, int i) {
  for (int k = 0; k < 3; ++k)
    ASSERT_EQ(float_to_bits(a[k]), float_to_bits(b[k])) << what << "[" << k << "], sample " << i;
}

/// Every field of sample `got` is `want`'s, to the bit.
void expect_same_sample(const LightSample& got, const LightSample& want, int i) {
  expect_same_bits(got.wi, want.wi, "wi", i);
  expect_same_bits(got.L, want.L, "L", i);
  expect_same_bits(got.target.p, want.target.p, "p", i);
  expect_same_bits(got.target.p_error, want.target.p_error, "p_error", i);
  expect_same_bits(got.target.n, want.target.n, "n", i);
  ASSERT_EQ(float_to_bits(got.pdf), float_to_bits(want.pdf)) << "pdf, sample " << i;
  ASSERT_EQ(float_to_bits(got.target.distance), float_to_bits(want.target.distance))
      << "distance, " << i;
  ASSERT_EQ(got.target.delta, want.target.delta) << "delta, sample " << i;
}

LightSample quad_sample_by_definition(const SampledLight& l, const glm::vec3& p, glm::vec2 u);

/// Shading point i of a bit-for-bit test: anywhere around panel_on_light's panel, on a plane of
/// zeros of either sign (every fifth), far away (every seventh) or on the panel (every eleventh).
SurfaceHit point_around_the_panel(Rng& rng, int i) {
  SurfaceHit at;
  at.p = glm::vec3(rng.next_float() * 6 - 3, rng.next_float() * 6 - 3, rng.next_float() * 6 - 3);
  if (i % 5 == 0) at.p[i % 3] = i % 2 ? 0.0f : -0.0f;
  if (i % 7 == 0) at.p *= 1e4f;
  if (i % 11 == 0) at.p = glm::vec3(0.1f, 0.05f, 1.0f);
  return at;
}

// A panel that is not its light's shape (a trapezoid) is sampled on the light's rectangle, seen
// from points all around it, some on the light itself, at zero coordinates of either sign and far
// away: every field of every sample is the definition's, to the bit. (A mesh's triangle seen
// under a usable solid angle is sampled by that solid angle, held to its density by the
// chi-square tests and light_set_near_field_test.)
/// Light 0's samples from 20000 points around its panel are quad_sample_by_definition's to the
/// bit, and more than 8000 of them reach it (`why` says which way they should).
void expect_quad_samples_by_definition(const SampledLights& lights, Rng rng, const char* why) {
  const SampledLight& l = lights.lights().at(0);
  long kept = 0;
  for (int i = 0; i < 20000; ++i) {
    const SurfaceHit at = point_around_the_panel(rng, i);
    const glm::vec2 u = rng.next_2d();
    const LightSample got = lights.make_sample(0, at, u);
    const LightSample want = quad_sample_by_definition(l, at.p, u);
    expect_same_sample(got, want, i);
    if (testing::Test::HasFatalFailure()) return;
    kept += want.pdf > 0.0f;
  }
  EXPECT_GT(kept, 8000) << why;
}

TEST(FrameworkSampledLights, APanelUnlikeItsLightIsSampledOnItsRectangleBitForBit) {
  Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  s.positions[3].x = -0.2f;  // a trapezoid: a panel of triangles, not a quad
  const uint32_t glow = test::add_material(s, glm::vec3(0), glm::vec3(2.0f, 3.0f, 4.0f));
  test::add_triangle(s, {-1, -0.5f, -1}, {1.5f, -0.7f, -1.2f}, {0.2f, 1.0f, -0.6f}, glow);
  const SampledLights lights(s);
  ASSERT_EQ(lights.lights().size(), 2u);
  const SampledLight& l = lights.lights()[0];
  ASSERT_EQ(l.kind, SampledLightKind::panel);
  ASSERT_TRUE(l.quad);
  EXPECT_EQ(l.corner, glm::vec3(-0.4f, -0.3f, 1.0f)) << "the light's corner, not the panel's";
  EXPECT_EQ(l.edge_u, glm::vec3(0.8f, 0, 0));
  EXPECT_EQ(l.edge_v, glm::vec3(0, 0.6f, 0));
  // The panel lies in the light's plane: its slack is only the rounding of a hit on it.
  EXPECT_GT(l.panel_slack.z, 0.0f);
  EXPECT_LT(glm::length(l.panel_slack), 1e-5f);
  ASSERT_EQ(lights.lights()[1].kind, SampledLightKind::mesh);
  expect_quad_samples_by_definition(lights, Rng(11, 4),
                                    "the samples from below the light should reach it");
}

TEST(FrameworkSampledLights, APanelThatMatchesItsLightSaysNothing) {
  const Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  const SampledLights lights(s);
  EXPECT_TRUE(lights.warnings().empty()) << lights.warnings().front();
  ASSERT_EQ(lights.lights().size(), 1u);
  EXPECT_EQ(lights.lights()[0].kind, SampledLightKind::panel);
}

TEST(FrameworkSampledLights, APanelThatDisagreesWithItsLightSaysWhatIsRendered) {
  struct Case {
    float emission;
    glm::vec3 u, v;
    const char* differs;
  };
  const Case cases[] = {
      {10.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, "differ in shape;"},      // CBspheres: turned round
      {20.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, "differ in radiance;"},   // brighter, same shape
      {20.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, "differ in shape and radiance;"},  // CBcoil
  };
  for (const Case& c : cases) {
    const Scene s = panel_on_light(0.4f, 0.3f, c.emission, c.u, c.v, 10.0f);
    const SampledLights lights(s);
    ASSERT_EQ(lights.warnings().size(), 1u) << c.differs;
    const std::string& w = lights.warnings()[0];
    EXPECT_NE(w.find(c.differs), std::string::npos) << w;
    EXPECT_NE(w.find("\"Lamp\""), std::string::npos) << w;
    EXPECT_NE(w.find("\"panel\""), std::string::npos) << w;
    EXPECT_NE(w.find("<light name=\"Lamp\">"), std::string::npos) << "names the element: " << w;
    EXPECT_NE(w.find("the light's rectangle with its radiance lights the scene"), std::string::npos)
        << w;
    EXPECT_NE(w.find("the panel, glowing with the light's radiance, is what the camera"),
              std::string::npos) << w;
  }
  const Scene coil = panel_on_light(0.4f, 0.3f, 20.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f);
  const std::string w = SampledLights(coil).warnings().at(0);
  EXPECT_NE(w.find("0.6 × 0.8, radiance 10)"), std::string::npos) << w;
  EXPECT_NE(w.find("0.8 × 0.6 along the light's edges, area 0.48, emission 20"), std::string::npos) << w;
}

// CBspheres' panel is 0.8 × 0.6 on a 0.6 × 0.8 light: light sampling samples the light's own
// rectangle with its radiance (as the course's renderer does), never where only the panel is.
TEST(FrameworkSampledLights, LightSamplesLandOnTheLightsRectangle) {
  const Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f);
  const SampledLights lights(s);
  ASSERT_EQ(lights.lights().size(), 1u);
  EXPECT_NEAR(lights.lights()[0].area, 0.48f, 1e-6f);
  SurfaceHit below;
  below.p = glm::vec3(0.3f, -0.1f, 0.0f);
  Rng rng(1);
  float reached_x = 0.0f, reached_y = 0.0f;
  for (int i = 0; i < 4000; ++i) {
    const LightSample ls = lights.make_sample(0, below, rng.next_2d());
    ASSERT_GT(ls.pdf, 0.0f);
    EXPECT_EQ(ls.L, glm::vec3(10.0f));
    ASSERT_LE(std::abs(ls.target.p.x), 0.3f + 1e-6f) << "the light is 0.6 across x";
    ASSERT_LE(std::abs(ls.target.p.y), 0.4f + 1e-6f);
    EXPECT_EQ(ls.target.p.z, 1.0f);
    const float d = ls.target.distance;
    EXPECT_NEAR(ls.pdf, d * d / (0.48f * ls.wi.z), 1e-4f * ls.pdf);
    reached_x = std::max(reached_x, std::abs(ls.target.p.x));
    reached_y = std::max(reached_y, std::abs(ls.target.p.y));
  }
  EXPECT_GT(reached_y, 0.39f) << "the samples cover the light's 0.8 along y, not the panel's 0.6";
  EXPECT_LT(reached_x, 0.3f + 1e-6f) << "and never the panel's 0.4 along x";
}

// The course's CBspheres_lambertian as its loader reads it: the area light's rectangle (0.6 along
// x, 0.8 along y, at z = 1.49, shining down; its panel is 0.8 × 0.6) is where light samples land,
// with the light's radiance, and one warning names the light.
TEST(FrameworkSampledLights, ACourseScenesLightSamplesLandOnTheAreaLightsRectangle) {
  const std::string path =
      std::string(test::shared_scenes_dir()) + "/sky/CBspheres_lambertian.dae";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "the course scenes are not at " << path;
  const Scene s = load_collada(path, [](const std::string&) {});
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& area = s.lights[0];
  ASSERT_EQ(area.kind, LightKind::area);
  EXPECT_NEAR(glm::length(area.edge_u), 0.6f, 1e-5f);
  EXPECT_NEAR(glm::length(area.edge_v), 0.8f, 1e-5f);
  const SampledLights lights(s);
  ASSERT_EQ(lights.lights().size(), 1u);
  ASSERT_EQ(lights.warnings().size(), 1u);
  SurfaceHit floor;
  floor.p = glm::vec3(0.2f, 0.1f, 0.0f);
  Rng rng(5);
  float reached_x = 0.0f, reached_y = 0.0f;
  for (int i = 0; i < 4000; ++i) {
    const LightSample ls = lights.make_sample(0, floor, rng.next_2d());
    ASSERT_GT(ls.pdf, 0.0f);
    EXPECT_EQ(ls.L, area.radiance);
    const glm::vec3 d = ls.target.p - area.position;
    ASSERT_LE(std::abs(d.x), 0.3f + 1e-5f) << "x " << ls.target.p.x;
    ASSERT_LE(std::abs(d.y), 0.4f + 1e-5f) << "y " << ls.target.p.y;
    ASSERT_NEAR(d.z, 0.0f, 1e-5f);
    reached_x = std::max(reached_x, std::abs(d.x));
    reached_y = std::max(reached_y, std::abs(d.y));
  }
  EXPECT_GT(reached_y, 0.39f) << "the light's 0.8 along y, not its panel's 0.6";
  EXPECT_GT(reached_x, 0.29f);
}

// The same light and panel, by ray: the camera (or a mirror) that hits the panel sees the light's
// radiance from below, nothing from above, even where only the panel is; a ray traced from a lit
// point for its direct light (emitted_along) receives the light where it crosses the light's
// rectangle, before anything but the panel, and pdf() is the light sample's density there.
TEST(FrameworkSampledLights, TheCameraSeesThePanelAndLitPointsReachTheRectangle) {
  const Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f);
  const SampledLights lights(s);
  SurfaceHit below;
  below.p = glm::vec3(0.3f, -0.1f, 0.0f);
  auto ray_to = [&](const glm::vec3& q) {
    Ray r;
    r.o = below.p;
    r.d = glm::normalize(q - below.p);
    return r;
  };
  const int k = lights.light_of_primitive(0);
  ASSERT_EQ(k, 0);
  EXPECT_EQ(lights.light_of_primitive(1), 0);

  // (0.35, 0.1): on the panel, off the light's rectangle.
  const glm::vec3 q(0.35f, 0.1f, 1.0f);
  const Ray r = ray_to(q);
  SurfaceHit on_panel = panel_hit(q, 0);
  on_panel.t = glm::length(q - below.p);
  EXPECT_EQ(lights.emitted(k, on_panel, r.d), glm::vec3(10.0f)) << "the camera sees the panel";
  EXPECT_EQ(lights.emitted_along(k, r, &on_panel), glm::vec3(0.0f))
      << "no light arrives from where only the panel is";
  EXPECT_EQ(lights.pdf(k, below, r.d, &on_panel), 0.0f) << "and no light sample comes from there";

  // (0.1, 0.35): on the rectangle, off the panel (a ray there hits what lies beyond, or nothing).
  const glm::vec3 q2(0.1f, 0.35f, 1.0f);
  const Ray r2 = ray_to(q2);
  const float d2 = glm::length(q2 - below.p);
  EXPECT_EQ(lights.emitted_along(k, r2, nullptr), glm::vec3(10.0f));
  SurfaceHit ceiling;
  ceiling.t = d2 * 1.01f;
  ceiling.primitive = 7;
  EXPECT_EQ(lights.emitted_along(k, r2, &ceiling), glm::vec3(10.0f)) << "the ceiling lies beyond";
  SurfaceHit blocker;
  blocker.t = d2 * 0.5f;
  blocker.primitive = 7;
  EXPECT_EQ(lights.emitted_along(k, r2, &blocker), glm::vec3(0.0f)) << "something nearer hides it";
  EXPECT_NEAR(lights.pdf(k, below, r2.d, nullptr), d2 * d2 / (0.48f * r2.d.z), 1e-4f);
  EXPECT_EQ(lights.radiance_along(r2, nullptr), glm::vec3(10.0f));

  // (0.1, 0.1): on both; the panel does not hide its own light.
  const glm::vec3 q3(0.1f, 0.1f, 1.0f);
  const Ray r3 = ray_to(q3);
  SurfaceHit on_both = panel_hit(q3, 0);
  on_both.t = glm::length(q3 - below.p);
  EXPECT_EQ(lights.emitted_along(k, r3, &on_both), glm::vec3(10.0f));

  // From above (the back): nothing by any view, and no density.
  SurfaceHit above;
  above.p = glm::vec3(0.1f, 0.1f, 1.5f);
  Ray down;
  down.o = above.p;
  down.d = glm::normalize(q3 - above.p);
  EXPECT_EQ(lights.emitted(k, on_both, down.d), glm::vec3(0.0f));
  EXPECT_EQ(lights.emitted_along(k, down, &on_both), glm::vec3(0.0f));
  EXPECT_EQ(lights.pdf(k, above, down.d, &on_both), 0.0f);
  EXPECT_EQ(lights.make_sample(0, above, {0.3f, 0.6f}).pdf, 0.0f);
}

// An area light with no panel stays the parallelogram it is: sampled, never hit.
TEST(FrameworkSampledLights, AnAreaLightWithoutAPanelCannotBeHit) {
  Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  s.materials[0].emission = glm::vec3(0.0f);
  s.materials[0].kind = MaterialKind::diffuse;
  const SampledLights lights(s);
  ASSERT_EQ(lights.lights().size(), 1u);
  EXPECT_EQ(lights.lights()[0].kind, SampledLightKind::parallelogram);
  EXPECT_FALSE(lights.lights()[0].can_be_hit());
  EXPECT_EQ(lights.light_of_primitive(0), -1);
  EXPECT_TRUE(lights.warnings().empty());
}


/// A sample of panel light `l` as its definition computes it in glm: the parallelogram's point
/// corner + u.x·edge_u + u.y·edge_v, its error box widened by panel_slack, the light's normal,
/// its 1 / area.
LightSample quad_sample_by_definition(const SampledLight& l, const glm::vec3& p, glm::vec2 u) {
  LightSample ls = surface_sample_by_definition(l, p, l.corner, u.x * l.edge_u, u.y * l.edge_v,
                                                l.normal, true);
  if (ls.target.distance < std::numeric_limits<float>::infinity())  // a sample was made
    ls.target.p_error += l.panel_slack;
  return ls;
}

/// Two emissive triangles on an area light of the same place: its panel, as the course's are.
Scene two_triangle_panel(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                         const glm::vec3& d) {
  Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  Light& l = s.lights[0];
  l.position = 0.25f * (a + b + c + d);
  l.edge_u = b - a;
  l.edge_v = d - a;
  l.direction = -glm::normalize(glm::cross(b - a, d - a));
  s.positions = {a, b, c, d};
  return s;
}

// A panel of two triangles that tile its light's parallelogram (every course light's where the
// two agree) is sampled on the panel's own parallelogram: its corners are the panel's. Any other
// panel (a trapezoid, triangles that share no edge, three triangles, another shape) is sampled on
// the light's rectangle.
TEST(FrameworkSampledLights, AQuadPanelIsSampledAsItsParallelogram) {
  {
    const SampledLights lights(panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f));
    const SampledLight& l = lights.lights().at(0);
    ASSERT_TRUE(l.quad);
    // The corner opposite the shared edge (0, 2) is vertex 1; its edges run to the edge's ends.
    EXPECT_EQ(l.corner, glm::vec3(0.4f, -0.3f, 1.0f));
    EXPECT_EQ(l.corner + l.edge_u, glm::vec3(0.4f, 0.3f, 1.0f));
    EXPECT_EQ(l.corner + l.edge_v, glm::vec3(-0.4f, -0.3f, 1.0f));
    EXPECT_LT(glm::length(l.panel_slack), 1e-5f);
  }
  const glm::vec3 light_corner(-0.4f, -0.3f, 1.0f);
  Scene trapezoid = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  trapezoid.positions[3].x = -0.2f;
  EXPECT_EQ(SampledLights(trapezoid).lights().at(0).corner, light_corner);
  Scene apart = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  apart.positions.push_back(apart.positions[0]);  // the same place, another vertex: no shared edge
  apart.positions.push_back(apart.positions[2]);
  apart.triangles[1] = Triangle{{4, 5, 3}, 0};
  EXPECT_EQ(SampledLights(apart).lights().at(0).corner, glm::vec3(0.4f, -0.3f, 1.0f))
      << "a shared edge is shared by position";
  apart.positions[5].x += 1e-3f;  // now the two meet at one corner only
  EXPECT_EQ(SampledLights(apart).lights().at(0).corner, light_corner);
  Scene three = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  three.positions.push_back({-0.2f, 0.1f, 1.0f});
  three.triangles[1] = Triangle{{0, 2, 4}, 0};
  three.triangles.push_back(Triangle{{4, 2, 3}, 0});
  three.triangles.push_back(Triangle{{0, 4, 3}, 0});
  EXPECT_EQ(SampledLights(three).lights().at(0).corner, light_corner);
  EXPECT_EQ(SampledLights(panel_on_light(0.4f, 0.3f, 10.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f))
                .lights().at(0).corner,
            glm::vec3(-0.3f, -0.4f, 1.0f))
      << "a panel turned round on its light: the light's rectangle";
}

// Every field of every quad sample is its definition's, to the bit, from points all around the
// panel, on it, at zeros of either sign and far away.
TEST(FrameworkSampledLights, QuadPanelSamplesAreTheirDefinitionBitForBit) {
  const Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  const SampledLights lights(s);
  const SampledLight& l = lights.lights().at(0);
  ASSERT_TRUE(l.quad);
  expect_quad_samples_by_definition(lights, Rng(12, 5),
                                    "the samples from below the panel should reach it");
}

/// The point of triangle (a, b, c) nearest q, in double (the regions of Ericson's Real-Time
/// Collision Detection, 5.1.5: a corner, an edge or the inside).
glm::dvec3 nearest_on_triangle(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b,
                               const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, aq = q - a;
  const double d1 = glm::dot(ab, aq), d2 = glm::dot(ac, aq);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bq = q - b;
  const double d3 = glm::dot(ab, bq), d4 = glm::dot(ac, bq);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cq = q - c;
  const double d5 = glm::dot(ab, cq), d6 = glm::dot(ac, cq);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// A quad that is a parallelogram only to rounding (turned about two axes, far from the origin,
// so no corner is exact): it is still found, and every sample's point lies within its error box
// of a point of the triangles (in double), which is what lets the shadow ray stop short of the
// light without meeting it. Near the origin, the same quad's samples fit their density.
TEST(FrameworkSampledLights, ARoundedQuadSamplesPointsWithinTheirErrorOfItsTriangles) {
  const glm::dvec3 o(1234.5, -987.25, 321.125), eu(0.37, 0.21, -0.13), ev(-0.11, 0.29, 0.17);
  const glm::vec3 a(o), b(o + eu), c(o + eu + ev), d(o + ev);
  const Scene s = two_triangle_panel(a, b, c, d);
  const SampledLights lights(s);
  const SampledLight& l = lights.lights().at(0);
  ASSERT_EQ(l.kind, SampledLightKind::panel);
  ASSERT_TRUE(l.quad);
  SurfaceHit at;
  at.p = glm::vec3(o - 2.0 * glm::cross(eu, ev) / glm::length(glm::cross(eu, ev)));
  Rng rng(3);
  int reached = 0;
  for (int i = 0; i < 20000; ++i) {
    const LightSample ls = lights.make_sample(0, at, rng.next_2d());
    if (!(ls.pdf > 0.0f)) continue;
    ++reached;
    // Within the error box of the nearest point of one of the two triangles.
    const glm::dvec3 q(ls.target.p);
    bool within = false;
    for (const Triangle& t : s.triangles) {
      const glm::dvec3 gap = glm::abs(q - nearest_on_triangle(q, glm::dvec3(s.positions[t.v[0]]),
                                                              glm::dvec3(s.positions[t.v[1]]),
                                                              glm::dvec3(s.positions[t.v[2]])));
      const glm::vec3& bound = ls.target.p_error;
      if (gap.x <= bound.x && gap.y <= bound.y && gap.z <= bound.z) within = true;
    }
    ASSERT_TRUE(within) << "sample " << i << " at " << q.x << " " << q.y << " " << q.z;
  }
  EXPECT_GT(reached, 19000);

  // The density: a slanted parallelogram seen from below, as the parallelogram light of
  // RectangleAreaLightBySolidAngleFitsItsDensity is.
  const Scene t = two_triangle_panel({-0.95f, -0.6f, 1.0f}, {0.65f, -0.6f, 1.0f},
                                     {0.95f, 0.6f, 1.0f}, {-0.65f, 0.6f, 1.0f});
  ASSERT_TRUE(SampledLights(t).lights().at(0).quad);
  expect_light_fits_its_density(t, glm::vec3(0.2f, -0.1f, 0.0f), {0, 0, 1});
}

// A panel may lie a hair in front of its light (the loader takes triangles within a thousandth of
// its size of the plane): every sample's error box takes the panel in, so no shadow ray towards
// the light from in front of the panel meets it; from between the panel and its light, unoccluded
// walks past it. Points all around, some a hair from the panel, some far.
TEST(FrameworkSampledLights, NoShadowRayMeetsItsOwnPanel) {
  for (float front : {0.0f, 2e-4f, 7e-4f}) {
    SCOPED_TRACE("panel in front of its light by " + std::to_string(front));
    Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f);
    for (glm::vec3& q : s.positions) q.z -= front;  // the light shines down
    const SampledLights lights(s);
    const SampledLight& l = lights.lights().at(0);
    ASSERT_EQ(l.kind, SampledLightKind::panel);
    const test::DoubleQuery query(s);
    Rng rng(3, 8);
    int made = 0, between = 0;
    for (int i = 0; i < 4000; ++i) {
      SurfaceHit at;
      at.p = glm::vec3(rng.next_float() * 2 - 1, rng.next_float() * 2 - 1,
                       1.0f - (i % 3 == 0 ? 3e-3f * rng.next_float() : 3.0f * rng.next_float()));
      if (i % 7 == 0) at.p *= 40.0f;
      at.ng = glm::vec3(0.0f, 0.0f, 1.0f);
      const LightSample ls = lights.make_sample(0, at, rng.next_2d());
      if (!(ls.pdf > 0.0f)) continue;
      ++made;
      const Ray ray = make_shadow_ray(at, ls);
      // From in front of the panel (beyond its slack), the ray ends short of it; from between
      // the panel and its light, unoccluded walks past it.
      SurfaceHit h;
      const float height = glm::dot(at.p - l.corner, l.normal);
      if (height > glm::dot(l.panel_slack, glm::abs(l.normal)))
        ASSERT_FALSE(query.intersect(ray, &h))
            << "the shadow ray from (" << at.p.x << ", " << at.p.y << ", " << at.p.z
            << ") meets its light's panel at t = " << h.t << " of " << ray.tmax;
      else
        ++between;
      ASSERT_TRUE(lights.unoccluded(query, ray, 0));
    }
    EXPECT_GT(made, 2000);
    if (front > 0.0f) EXPECT_GT(between, 10) << "points between the panel and its light";
  }
}

}  // namespace
}  // namespace pt
