// The light set's samples of each kind of light, as directions from a point, against the density
// LightSet::pdf claims for them: chi-square at significance 0.01 (Nori's level), and each density
// integrates to 1.
#include "framework/lights/light_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "framework/sampling/chi2_test_util.h"
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

}  // namespace
}  // namespace pt
