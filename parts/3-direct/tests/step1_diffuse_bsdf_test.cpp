// Part 3, step 1 (diffuse_bsdf): the Lambertian BSDF's value, its samples against the density it
// claims (chi-square at significance 0.01), and the estimator weight its samples give.
#include "parts/3-direct/diffuse_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "framework/math/frame.h"
#include "framework/sampling/chi2_test_util.h"
#include "framework/sampling/rng.h"
#include "framework/testing/lighting_rig.h"

namespace pt {
namespace {

// bsdf.h's convention: sample_f returns f itself (not f·cos/pdf) and sets the density; the
// caller forms the weight f·|cosθ|/pdf, which for a Lambertian surface averages to its albedo.
TEST(diffuse_bsdf, sample_f_returns_f_draws_its_pdf_and_the_weight_averages_to_the_albedo) {
  DiffuseBsdf bsdf(glm::vec3(0.5f, 0.25f, 1.0f));
  const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f));
  bool consistent = true;
  const Chi2Result r = chi2_direction_test(
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
      [&](const glm::vec3& w) { return double(bsdf.pdf(wo, w)); }, Frame({0, 0, 1}));
  EXPECT_TRUE(chi2_fits(r)) << r.summary;
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
  const char* what = "the mean weight f·cosθ/pdf of sample_f's draws, which is the albedo";
  EXPECT_NEAR(sum.x / n, 0.5, 1e-4)
      << what << ": " << sum.x / n << " for albedo 0.5"
      << test::ratio_hint(sum.x / n, 0.5,
                          {{0.5, "f is albedo/(2π), not albedo/π?"},
                           {M_PI, "f is the albedo itself, without the 1/π?"},
                           {4.0 / 3.0, "cosine-weighted directions given the uniform density 1/(2π)? (theirs is cosθ/π)"}});
  EXPECT_NEAR(sum.y / n, 0.25, 1e-4) << what << ": " << sum.y / n << " for albedo 0.25";
}


// f itself, per channel, at directions all over the sphere: albedo/π for every wi above the
// surface (wi.z > 0), whatever wo, and exactly zero below it (wi.z < 0), where a surface lit from
// behind must reflect nothing. sample_f only draws directions above, so its checks cannot see f
// below the surface.
TEST(diffuse_bsdf, f_is_albedo_over_pi_above_the_surface_and_zero_below) {
  const glm::vec3 albedo(0.5f, 0.25f, 1.0f);
  DiffuseBsdf bsdf(albedo);
  const glm::vec3 wos[] = {glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f)), glm::vec3(0, 0, 1)};
  const glm::vec3 wis[] = {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.6f, 0.3f, 0.2f)),
                           glm::normalize(glm::vec3(-0.9f, 0.1f, 0.05f)), glm::vec3(0, 0, -1),
                           glm::normalize(glm::vec3(0.4f, -0.5f, -0.3f)),
                           glm::normalize(glm::vec3(-0.2f, 0.7f, -0.9f))};
  for (const glm::vec3& wo : wos)
    for (const glm::vec3& wi : wis) {
      const glm::vec3 f = bsdf.f(wo, wi);
      const glm::vec3 want = wi.z > 0.0f ? albedo * float(1.0 / M_PI) : glm::vec3(0.0f);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(f[c], want[c], 1e-6f)
            << "f(wo, wi) channel " << c << " for wi = (" << wi.x << ", " << wi.y << ", " << wi.z
            << "), " << (wi.z > 0.0f ? "above" : "below") << " the surface, albedo " << albedo[c]
            << ": got " << f[c] << ", want " << want[c]
            << (wi.z > 0.0f ? test::ratio_hint(f[c], want[c],
                                               {{0.5, "albedo/(2π), not albedo/π?"},
                                                {M_PI, "the albedo itself, without the 1/π?"}})
                            : std::string(": a Lambertian surface reflects nothing for a wi below "
                                          "it (wi.z <= 0): f must be zero there"));
    }
}

}  // namespace
}  // namespace pt
