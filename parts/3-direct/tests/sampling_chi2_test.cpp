// Chi-square goodness-of-fit of every sampling routine lighting relies on, against the density it
// claims, at significance 0.01 per test (Nori's level); and each density integrates to 1.
#include <gtest/gtest.h>

#include <cmath>

#include "3-direct/diffuse_bsdf.h"
#include "3-direct/tests/test_scenes.h"
#include "bsdf/specular.h"
#include "lights/light_set.h"
#include "sampling/chi2_test_util.h"
#include "sampling/warp.h"

namespace pt {
namespace {

constexpr double kAlpha = 0.01;

void expect_fits(const Chi2Result& r) {
  EXPECT_EQ(r.nonfinite, 0) << r.summary;
  EXPECT_GT(r.p_value, kAlpha) << r.summary;
  EXPECT_NEAR(r.pdf_integral, 1.0, 2e-3) << r.summary;
}

TEST(Part3Sampling, UniformHemisphereFitsItsDensity) {
  expect_fits(chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_hemisphere(u); return true; },
      [](const glm::vec3& w) { return double(uniform_hemisphere_pdf(w)); }, Frame({0, 0, 1})));
}

TEST(Part3Sampling, CosineHemisphereFitsItsDensity) {
  expect_fits(chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_cosine_hemisphere(u); return true; },
      [](const glm::vec3& w) { return double(cosine_hemisphere_pdf(w)); }, Frame({0, 0, 1})));
}

TEST(Part3Sampling, UniformSphereFitsItsDensity) {
  expect_fits(chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_sphere(u); return true; },
      [](const glm::vec3&) { return double(uniform_sphere_pdf()); }, Frame({0, 0, 1})));
}

// A test must be able to fail: the cosine sampler checked against the uniform density is
// rejected.
TEST(Part3Sampling, ChiSquareRejectsAWrongDensity) {
  Chi2Result r = chi2_direction_test(
      [](glm::vec2 u, glm::vec3* w) { *w = square_to_cosine_hemisphere(u); return true; },
      [](const glm::vec3& w) { return double(uniform_hemisphere_pdf(w)); }, Frame({0, 0, 1}));
  EXPECT_LT(r.p_value, kAlpha) << r.summary;
}

TEST(Part3Sampling, DiffuseBsdfSamplesItsPdfAndWeightIsFCosOverPdf) {
  DiffuseBsdf bsdf(glm::vec3(0.5f, 0.25f, 1.0f));
  const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f));
  bool consistent = true;
  expect_fits(chi2_direction_test(
      [&](glm::vec2 u, glm::vec3* w) {
        float pdf = 0.0f;
        glm::vec3 f = bsdf.sample_f(wo, u, w, &pdf);
        if (!(pdf > 0.0f)) return false;
        // The returned value is f(wo, wi) and the density is pdf(wo, wi).
        glm::vec3 expect_f = bsdf.f(wo, *w);
        if (glm::length(f - expect_f) > 1e-6f || std::abs(pdf - bsdf.pdf(wo, *w)) > 1e-5f * pdf)
          consistent = false;
        return true;
      },
      [&](const glm::vec3& w) { return double(bsdf.pdf(wo, w)); }, Frame({0, 0, 1})));
  EXPECT_TRUE(consistent) << "sample_f's value or density disagrees with f() or pdf()";
  // ∫ f cos dω = albedo for a Lambertian surface: checked through the estimator's weight.
  Rng rng(7);
  glm::dvec3 sum(0.0);
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    glm::vec3 wi;
    float pdf;
    glm::vec3 f = bsdf.sample_f(wo, rng.next_2d(), &wi, &pdf);
    sum += glm::dvec3(f * wi.z / pdf);
  }
  EXPECT_NEAR(sum.x / n, 0.5, 1e-4);
  EXPECT_NEAR(sum.y / n, 0.25, 1e-4);
}

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

TEST(Part3Sampling, TriangleLightBySolidAngleFitsItsDensity) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0), glm::vec3(1));
  test::add_triangle(s, {-1, -0.5f, 1}, {1.5f, -0.7f, 1.2f}, {0.2f, 1.0f, 0.6f}, m);
  SurfaceHit at;
  at.p = glm::vec3(0.1f, 0.0f, 0.0f);
  Chi2Options opt;
  opt.quadrature = 96;  // edges cut cells: a fine quadrature keeps their expected share exact
  expect_fits(light_chi2(s, at, {0.1f, 0.0f, 1.0f}, opt));
}

TEST(Part3Sampling, RectangleAreaLightBySolidAngleFitsItsDensity) {
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
  expect_fits(light_chi2(s, at, {0, 0, 1}, opt));
}

// An area light seen through a panel that is not its shape (CBcoil's 0.8 × 0.6 panel on a
// 0.6 × 0.8 light): its samples are directions to the panel, with the density pdf() gives the
// panel point a ray in that direction reaches.
TEST(Part3Sampling, AreaLightPanelBySolidAngleFitsItsDensity) {
  Scene s = test::disagreeing_panel_scene();
  SurfaceHit at;
  at.p = glm::vec3(0.4f, 0.0f, 0.0f);
  Chi2Options opt;
  opt.quadrature = 96;  // edges cut cells: a fine quadrature keeps their expected share exact
  expect_fits(light_chi2(s, at, {-0.4f, 0.0f, 0.5f}, opt));
}

TEST(Part3Sampling, SphereLightConeFitsItsDensity) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0), glm::vec3(1));
  // Radius sqrt(1.75) at distance 2: the cone's rim is at cosθ = 0.75, an edge of the test's
  // grid, so the midpoint quadrature integrates every cell exactly.
  s.spheres.push_back(Sphere{glm::vec3(0.0f, 0.0f, 2.0f), std::sqrt(1.75f), m});
  SurfaceHit at;
  at.p = glm::vec3(0.0f);
  Chi2Options opt;
  opt.quadrature = 8;
  expect_fits(light_chi2(s, at, {0, 0, 1}, opt));
}

TEST(Part3Sampling, EnvironmentMapFitsItsDensity) {
  EnvironmentMap env;
  std::vector<glm::vec3> px(16 * 8);
  // Black polar rows: the density per steradian has a 1/sinθ factor there that the midpoint
  // quadrature of the test could not integrate accurately.
  for (int i = 0; i < int(px.size()); ++i)
    px[i] = (i < 16 || i >= 7 * 16) ? glm::vec3(0.0f) : glm::vec3(float(1 + (i * 7) % 5));
  px[3 * 16 + 5] = glm::vec3(50.0f);  // a sun
  env.set_pixels(16, 8, px);
  Chi2Options opt;
  opt.quadrature = 48;  // edges cut cells: a fine quadrature keeps their expected share exact
  expect_fits(chi2_direction_test(
      [&](glm::vec2 u, glm::vec3* w) {
        float pdf;
        *w = env.sample(u, &pdf);
        return pdf > 0.0f;
      },
      [&](const glm::vec3& w) { return double(env.pdf(w)); }, Frame({0, 1, 0}), opt));
}

// Glass picks reflection with the Fresnel probability: a two-cell goodness of fit (binomial), at
// significance 0.01, and each choice's weight is reflectance or transmittance scaled for radiance.
TEST(Part3Sampling, GlassChoosesReflectionWithFresnelProbability) {
  GlassBsdf glass(glm::vec3(1.0f), glm::vec3(1.0f), 1.5f);
  const glm::vec3 wo = glm::normalize(glm::vec3(0.8f, 0.0f, 0.3f));
  const double F = fresnel_dielectric(wo.z, 1.5f);
  ASSERT_GT(F, 0.05);
  ASSERT_LT(F, 0.95);
  Rng rng(3);
  const int n = 40000;
  int reflected = 0;
  for (int i = 0; i < n; ++i) {
    glm::vec3 wi;
    float pdf;
    glm::vec3 f = glass.sample_f(wo, rng.next_2d(), &wi, &pdf);
    ASSERT_GT(pdf, 0.0f);
    glm::vec3 weight = f * std::abs(wi.z) / pdf;
    if (wi.z > 0) {
      ++reflected;
      EXPECT_NEAR(weight.x, 1.0f, 1e-4f);
    } else {
      EXPECT_NEAR(weight.x, 1.0f / (1.5f * 1.5f), 1e-4f);
    }
  }
  double expected = F * n, sd = std::sqrt(n * F * (1 - F));
  EXPECT_LT(std::abs(reflected - expected) / sd, 2.576) << "F = " << F << ", reflected " << reflected;
}

}  // namespace
}  // namespace pt
