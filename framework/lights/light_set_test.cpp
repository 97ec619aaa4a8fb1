// LightSet: the samples of each kind of light, as directions from a point, against the density
// LightSet::pdf claims for them (chi-square at significance 0.01, Nori's level; each density
// integrates to 1); and the emitter rule: an area light and the panel on it are one emitter (the
// panel's triangles with the light's radiance, one-sided), and a panel that disagrees with its
// light says so once.
#include "framework/lights/light_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "framework/math/float_error.h"
#include "framework/sampling/chi2_test_util.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/testing/test_scenes.h"

namespace pt {
namespace {

// The light samples of one light as directions from a point, against LightSet::pdf.
Chi2Result light_chi2(const Scene& scene, const SurfaceHit& at, const glm::vec3& aim,
                      Chi2Options opt = {}) {
  LightSet lights(scene);
  test::DoubleQuery query(scene);
  return chi2_direction_test(
      [&](glm::vec2 u, glm::vec3* w) {
        LightSample ls = lights.sample(0, at, u);
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

TEST(FrameworkLightSet, TriangleLightBySolidAngleFitsItsDensity) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0), glm::vec3(1));
  test::add_triangle(s, {-1, -0.5f, 1}, {1.5f, -0.7f, 1.2f}, {0.2f, 1.0f, 0.6f}, m);
  SurfaceHit at;
  at.p = glm::vec3(0.1f, 0.0f, 0.0f);
  Chi2Options opt;
  opt.quadrature = 96;  // edges cut cells: a fine quadrature keeps their expected share exact
  const Chi2Result r = light_chi2(s, at, {0.1f, 0.0f, 1.0f}, opt);
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

TEST(FrameworkLightSet, RectangleAreaLightBySolidAngleFitsItsDensity) {
  Scene s;
  Light l;
  l.kind = LightKind::area;
  l.position = glm::vec3(0.0f, 0.0f, 1.0f);
  l.edge_u = glm::vec3(1.6f, 0.0f, 0.0f);
  l.edge_v = glm::vec3(0.3f, 1.2f, 0.0f);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  s.lights.push_back(l);
  SurfaceHit at;
  at.p = glm::vec3(0.2f, -0.1f, 0.0f);
  Chi2Options opt;
  opt.quadrature = 96;  // edges cut cells: a fine quadrature keeps their expected share exact
  const Chi2Result r = light_chi2(s, at, {0, 0, 1}, opt);
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

// An area light seen through a panel that is not its shape (CBcoil's 0.8 × 0.6 panel on a
// 0.6 × 0.8 light): its samples are directions to the panel, with the density pdf() gives the
// panel point a ray in that direction reaches.
TEST(FrameworkLightSet, AreaLightPanelBySolidAngleFitsItsDensity) {
  Scene s = test::disagreeing_panel_scene();
  SurfaceHit at;
  at.p = glm::vec3(0.4f, 0.0f, 0.0f);
  Chi2Options opt;
  opt.quadrature = 96;  // edges cut cells: a fine quadrature keeps their expected share exact
  const Chi2Result r = light_chi2(s, at, {-0.4f, 0.0f, 0.5f}, opt);
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
}

TEST(FrameworkLightSet, SphereLightConeFitsItsDensity) {
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

/// A sample of panel or mesh light `l` as its definition computes it in glm, one component at a
/// time: LightSet::sample does these operations in SIMD lanes where the build has them, and must
/// give the same bits.
LightSample triangle_sample_by_definition(const SampledLight& l, const glm::vec3& p, glm::vec2 u,
                                          bool one_sided) {
  int cell;
  const float x = l.triangle_pick.sample_continuous(u.x, nullptr, &cell);
  const float u0 = std::clamp(x * float(l.triangle_pick.size()) - float(cell), 0.0f, 1.0f);
  const SampledLight::SampledTriangle& t = l.sampled_triangles[cell];
  if (t.n == glm::vec3(0.0f)) return {};
  const glm::vec3 bary = square_to_uniform_triangle({u0, u.y});
  const glm::vec3 q = bary.x * t.a + bary.y * t.b + bary.z * t.c;
  const glm::vec3 d = q - p;
  const float dist = glm::length(d);
  if (!(dist > 0.0f) || !std::isfinite(dist)) return {};
  LightSample ls;
  ls.wi = d / dist;
  ls.distance = dist;
  ls.p = q;
  ls.p_error = gamma(6) * (glm::abs(bary.x * t.a) + glm::abs(bary.y * t.b) + glm::abs(bary.z * t.c));
  ls.n = t.n;
  const float cos_l = glm::dot(-ls.wi, t.n);
  if (one_sided && !(cos_l > 0.0f)) return {};
  ls.pdf = area_to_solid_angle_pdf(1.0f / l.area, dist, cos_l);
  ls.L = ls.pdf > 0.0f ? l.radiance : glm::vec3(0.0f);
  return ls;
}

void expect_same_bits(const glm::vec3& a, const glm::vec3& b, const char* what, int i) {
  for (int k = 0; k < 3; ++k)
    ASSERT_EQ(float_to_bits(a[k]), float_to_bits(b[k])) << what << "[" << k << "], sample " << i;
}

// Panels (one-sided) and meshes (two-sided), seen from points all around them, some on the light
// itself, at zero coordinates of either sign and far away: every field of every sample is the
// definition's, to the bit.
TEST(FrameworkLightSet, TriangleLightSamplesAreTheirDefinitionBitForBit) {
  Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  const uint32_t glow = test::add_material(s, glm::vec3(0), glm::vec3(2.0f, 3.0f, 4.0f));
  test::add_triangle(s, {-1, -0.5f, -1}, {1.5f, -0.7f, -1.2f}, {0.2f, 1.0f, -0.6f}, glow);
  test::add_triangle(s, {2, 2, 2}, {3, 2, 2.5f}, {2, 4, 2}, glow);
  // In the plane x = -0: the error bound's x is glm::abs's sum of -0s, which is -0.
  test::add_triangle(s, {-0.0f, 1, 2}, {-0.0f, 2, 2}, {-0.0f, 1, 3}, glow);
  const LightSet lights(s);
  ASSERT_EQ(lights.lights().size(), 2u);
  ASSERT_EQ(lights.lights()[0].kind, SampledLightKind::panel);
  ASSERT_EQ(lights.lights()[1].kind, SampledLightKind::mesh);
  Rng rng(11, 4);
  long kept = 0;
  for (int i = 0; i < 20000; ++i) {
    SurfaceHit at;
    at.p = glm::vec3(rng.next_float() * 6 - 3, rng.next_float() * 6 - 3, rng.next_float() * 6 - 3);
    if (i % 5 == 0) at.p[i % 3] = i % 2 ? 0.0f : -0.0f;
    if (i % 7 == 0) at.p *= 1e4f;
    if (i % 11 == 0) at.p = glm::vec3(0.1f, 0.05f, 1.0f);  // on the panel
    const glm::vec2 u = rng.next_2d();
    for (int k = 0; k < 2; ++k) {
      const LightSample got = lights.sample(k, at, u);
      const LightSample want = triangle_sample_by_definition(lights.lights()[k], at.p, u, k == 0);
      expect_same_bits(got.wi, want.wi, "wi", i);
      expect_same_bits(got.L, want.L, "L", i);
      expect_same_bits(got.p, want.p, "p", i);
      expect_same_bits(got.p_error, want.p_error, "p_error", i);
      expect_same_bits(got.n, want.n, "n", i);
      ASSERT_EQ(float_to_bits(got.pdf), float_to_bits(want.pdf)) << "pdf, sample " << i;
      ASSERT_EQ(float_to_bits(got.distance), float_to_bits(want.distance)) << "distance, " << i;
      ASSERT_EQ(got.delta, want.delta);
      kept += want.pdf > 0.0f;
    }
  }
  EXPECT_GT(kept, 20000) << "most samples should reach the point";
}

TEST(FrameworkLightSet, APanelThatMatchesItsLightSaysNothing) {
  const Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  const LightSet lights(s);
  EXPECT_TRUE(lights.warnings().empty()) << lights.warnings().front();
  ASSERT_EQ(lights.lights().size(), 1u);
  EXPECT_EQ(lights.lights()[0].kind, SampledLightKind::panel);
}

TEST(FrameworkLightSet, APanelThatDisagreesWithItsLightSaysWhatIsRendered) {
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
    const LightSet lights(s);
    ASSERT_EQ(lights.warnings().size(), 1u) << c.differs;
    const std::string& w = lights.warnings()[0];
    EXPECT_NE(w.find(c.differs), std::string::npos) << w;
    EXPECT_NE(w.find("\"Lamp\""), std::string::npos) << w;
    EXPECT_NE(w.find("\"panel\""), std::string::npos) << w;
    EXPECT_NE(w.find("the panel's shape"), std::string::npos) << w;
    EXPECT_NE(w.find("the light's radiance"), std::string::npos) << w;
  }
  const Scene coil = panel_on_light(0.4f, 0.3f, 20.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f);
  const std::string w = LightSet(coil).warnings().at(0);
  EXPECT_NE(w.find("(0.6 × 0.8, radiance 10)"), std::string::npos) << w;
  EXPECT_NE(w.find("0.8 × 0.6 along the light's edges, area 0.48, emission 20"), std::string::npos) << w;
}

// Light sampling samples what a ray can hit: points on the panel's triangles (never where only
// the light's parallelogram reaches), with the light's radiance; a ray that reaches the panel
// from below sees that radiance, from above nothing, and pdf() agrees on both sides.
TEST(FrameworkLightSet, ThePanelIsWhatIsSampledAndWhatIsSeen) {
  const Scene s = panel_on_light(0.4f, 0.3f, 20.0f, {0.6f, 0, 0}, {0, 0.8f, 0}, 10.0f);
  const LightSet lights(s);
  ASSERT_EQ(lights.lights().size(), 1u);
  EXPECT_NEAR(lights.lights()[0].area, 0.48f, 1e-6f);
  SurfaceHit below;
  below.p = glm::vec3(0.3f, -0.1f, 0.0f);
  Rng rng(1);
  float reached_x = 0.0f, reached_y = 0.0f;
  for (int i = 0; i < 4000; ++i) {
    const LightSample ls = lights.sample(0, below, rng.next_2d());
    ASSERT_GT(ls.pdf, 0.0f);
    EXPECT_EQ(ls.L, glm::vec3(10.0f));
    ASSERT_LE(std::abs(ls.p.x), 0.4f + 1e-6f);
    ASSERT_LE(std::abs(ls.p.y), 0.3f + 1e-6f);
    EXPECT_EQ(ls.p.z, 1.0f);
    reached_x = std::max(reached_x, std::abs(ls.p.x));
    reached_y = std::max(reached_y, std::abs(ls.p.y));
  }
  EXPECT_GT(reached_x, 0.39f) << "the samples cover the panel's width, not the light's 0.3";
  EXPECT_LT(reached_y, 0.3f + 1e-6f) << "and never the light's 0.4";

  // A ray from `below` up to the panel's point (0.35, 0.1): outside the light, inside the panel.
  const glm::vec3 q(0.35f, 0.1f, 1.0f);
  const glm::vec3 wi = glm::normalize(q - below.p);
  const int k = lights.light_of_primitive(0);
  ASSERT_EQ(k, 0);
  EXPECT_EQ(lights.light_of_primitive(1), 0);
  const SurfaceHit on_panel = panel_hit(q, 0);
  EXPECT_EQ(lights.emitted(k, on_panel, wi), glm::vec3(10.0f));
  const float d = glm::length(q - below.p);  // the panel faces down: cosθ at it is wi.z
  EXPECT_NEAR(lights.pdf(k, below, wi, &on_panel), d * d / (0.48f * wi.z), 1e-4f);
  // From above the panel (its back): no light, and no density.
  SurfaceHit above;
  above.p = glm::vec3(0.3f, 0.1f, 1.5f);
  const glm::vec3 down = glm::normalize(q - above.p);
  EXPECT_EQ(lights.emitted(k, on_panel, down), glm::vec3(0.0f));
  EXPECT_EQ(lights.pdf(k, above, down, &on_panel), 0.0f);
  EXPECT_EQ(lights.sample(0, above, {0.3f, 0.6f}).pdf, 0.0f);
}

// An area light with no panel stays the parallelogram it is: sampled, never hit.
TEST(FrameworkLightSet, AnAreaLightWithoutAPanelCannotBeHit) {
  Scene s = panel_on_light(0.4f, 0.3f, 10.0f, {0.8f, 0, 0}, {0, 0.6f, 0}, 10.0f);
  s.materials[0].emission = glm::vec3(0.0f);
  s.materials[0].kind = MaterialKind::diffuse;
  const LightSet lights(s);
  ASSERT_EQ(lights.lights().size(), 1u);
  EXPECT_EQ(lights.lights()[0].kind, SampledLightKind::parallelogram);
  EXPECT_FALSE(lights.lights()[0].can_be_hit());
  EXPECT_EQ(lights.light_of_primitive(0), -1);
  EXPECT_TRUE(lights.warnings().empty());
}

}  // namespace
}  // namespace pt
