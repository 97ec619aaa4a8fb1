// Not needed for the assignment.
// The course's microfacet BRDF: its distribution's normalisation, the conductor Fresnel at a
// known angle, its samples against the density it claims (chi-square at significance 0.01),
// sample_f's value and density against f and pdf, and a furnace-style energy bound.
#include "framework/bsdf/microfacet_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "framework/math/frame.h"
#include "framework/sampling/chi2_test_util.h"
#include "framework/sampling/rng.h"

namespace pt {
namespace {

// Gold's complex index of refraction, roughly as tabulated at red, green and blue wavelengths:
// a strongly coloured conductor.
const glm::vec3 kGoldEta(0.21646f, 0.42833f, 1.3284f), kGoldK(3.2390f, 2.4599f, 1.8661f);

// ∫ over the hemisphere of g(w) dω by the midpoint rule in (cosθ, φ), which has equal solid
// angle cells.
template <class G>
glm::dvec3 hemisphere_integral(G g, int nc = 2000, int np = 1000) {
  glm::dvec3 sum(0.0);
  const double dc = 1.0 / nc, dp = 2.0 * M_PI / np;
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < np; ++j) {
      const double c = (i + 0.5) * dc, phi = (j + 0.5) * dp, s = std::sqrt(1.0 - c * c);
      sum += glm::dvec3(g(glm::vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c))));
    }
  return sum * dc * dp;
}

TEST(FrameworkMicrofacet, BeckmannDistributionIntegratesToOneOverProjectedArea) {
  for (float alpha : {0.1f, 0.3f, 0.5f, 0.8f}) {
    MicrofacetBsdf bsdf(alpha, glm::vec3(1.0f), glm::vec3(0.0f));
    // ∫ D(h) cosθh dω = 1: the microfacets' projected area is the macro surface's.
    const glm::dvec3 area = hemisphere_integral(
        [&](const glm::vec3& h) { return glm::vec3(bsdf.distribution(h) * h.z); }, 2000, 8);
    EXPECT_NEAR(area.x, 1.0, 2e-3) << "alpha " << alpha;
  }
}

TEST(FrameworkMicrofacet, ConductorFresnelAtNormalIncidenceIsTheKnownReflectance) {
  // At cosθ = 1 both polarisations give ((η − 1)² + k²) / ((η + 1)² + k²).
  const glm::vec3 F = fresnel_conductor(1.0f, kGoldEta, kGoldK);
  for (int c = 0; c < 3; ++c) {
    const float e = kGoldEta[c], k = kGoldK[c];
    EXPECT_NEAR(F[c], ((e - 1) * (e - 1) + k * k) / ((e + 1) * (e + 1) + k * k), 1e-6f) << c;
  }
  EXPECT_GT(F.x, F.z);  // gold reflects red more than blue
  // At grazing incidence every conductor reflects everything.
  const glm::vec3 grazing = fresnel_conductor(0.0f, kGoldEta, kGoldK);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(grazing[c], 1.0f, 1e-6f);
  // η = k = 0 is a perfect reflector at every angle: the furnace below uses it.
  for (float c : {0.1f, 0.5f, 1.0f}) EXPECT_NEAR(fresnel_conductor(c, glm::vec3(0.0f), glm::vec3(0.0f)).x, 1.0f, 1e-6f);
}

// Its samples follow pdf (the cell of draws that reflect below the surface is expected to hold
// 1 − ∫pdf), pdf integrates to at most 1, and each draw's value and density are f's and pdf's.
TEST(FrameworkMicrofacet, SamplesFollowTheirDensityAndAgreeWithFAndPdf) {
  struct Case {
    float alpha;
    glm::vec3 wo;
  };
  const Case cases[] = {{0.5f, glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f))},
                        {0.25f, glm::normalize(glm::vec3(0.0f, 0.0f, 1.0f))},
                        {0.25f, glm::normalize(glm::vec3(-0.7f, 0.4f, 0.3f))},
                        {0.8f, glm::normalize(glm::vec3(0.9f, 0.1f, 0.15f))}};
  for (const Case& c : cases) {
    MicrofacetBsdf bsdf(c.alpha, kGoldEta, kGoldK);
    const std::string what = "alpha " + std::to_string(c.alpha) + ", wo.z " + std::to_string(c.wo.z);
    long inconsistent = 0;
    const Chi2Result r = chi2_direction_test(
        [&](glm::vec2 u, glm::vec3* w) {
          float pdf = 0.0f;
          const glm::vec3 f = bsdf.sample_f(c.wo, u, w, &pdf);
          if (!(pdf > 0.0f)) return false;
          const glm::vec3 expect_f = bsdf.f(c.wo, *w);
          if (glm::length(f - expect_f) > 1e-5f * (1.0f + glm::length(expect_f)) ||
              std::abs(pdf - bsdf.pdf(c.wo, *w)) > 1e-5f * pdf)
            ++inconsistent;
          return true;
        },
        [&](const glm::vec3& w) { return double(bsdf.pdf(c.wo, w)); },
        // The pole on the normal, so that the horizon, where the density drops to zero, is a
        // boundary of cells rather than a cut through them that the quadrature would misjudge.
        Frame(glm::vec3(0.0f, 0.0f, 1.0f)), Chi2Options{64, 64, 12, 300000, 5.0, 5});
    EXPECT_EQ(r.nonfinite, 0) << what;
    EXPECT_GT(r.p_value, 0.01) << what << ": " << r.summary;
    EXPECT_LE(r.pdf_integral, 1.0 + 2e-3) << what << ": " << r.summary;
    EXPECT_GT(r.pdf_integral, 0.5) << what << ": " << r.summary;
    EXPECT_EQ(inconsistent, 0) << what << ": sample_f's value or density disagrees with f or pdf";
  }
}

// A furnace: the albedo ∫ f(wo, wi) cosθi dωi is at most 1 in every channel, for a perfect
// reflector (F = 1) and for gold, at every angle; for a smooth perfect reflector seen from above
// it is close to 1 (what a missing 1/π or a D off by cos θh would move far away). The estimator
// f·cos/pdf of sample_f's draws agrees with the quadrature.
TEST(FrameworkMicrofacet, FurnaceAlbedoIsAtMostOne) {
  for (float alpha : {0.1f, 0.3f, 0.5f, 0.9f})
    for (float cos_o : {1.0f, 0.7f, 0.3f, 0.05f}) {
      const glm::vec3 wo(std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o);
      for (bool gold : {false, true}) {
        MicrofacetBsdf bsdf(alpha, gold ? kGoldEta : glm::vec3(0.0f), gold ? kGoldK : glm::vec3(0.0f));
        const glm::dvec3 albedo =
            hemisphere_integral([&](const glm::vec3& wi) { return bsdf.f(wo, wi) * wi.z; });
        const std::string what = std::string(gold ? "gold" : "white") + ", alpha " +
                                 std::to_string(alpha) + ", cos θo " + std::to_string(cos_o);
        for (int ch = 0; ch < 3; ++ch) {
          EXPECT_LE(albedo[ch], 1.0 + 2e-3) << what << " channel " << ch;
          EXPECT_GE(albedo[ch], 0.0) << what;
        }
        if (!gold && alpha <= 0.3f && cos_o >= 0.7f) {
          EXPECT_GT(albedo.x, 0.9) << what << ": a smooth perfect reflector loses little";
        }
        Rng rng(11);
        glm::dvec3 sum(0.0);
        const int n = 50000;
        for (int i = 0; i < n; ++i) {
          glm::vec3 wi;
          float pdf;
          const glm::vec3 f = bsdf.sample_f(wo, rng.next_2d(), &wi, &pdf);
          if (pdf > 0.0f) sum += glm::dvec3(f * wi.z / pdf);
        }
        EXPECT_NEAR(sum.x / n, albedo.x, 0.01 + 0.01 * albedo.x) << what << ": estimator mean";
      }
    }
}

}  // namespace
}  // namespace pt
