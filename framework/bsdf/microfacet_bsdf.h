// Not needed for the assignment.
// The course's rough conductor: a Beckmann microfacet BRDF with a conductor's Fresnel term.
#pragma once

#include <glm/vec3.hpp>

#include "framework/bsdf/bsdf.h"

namespace pt {

/// Unpolarised Fresnel reflectance of a conductor of complex index eta + i·k (per channel) for
/// light arriving under cosine cos_i, in the approximation the course uses (Rs and Rp with the
/// conductor's η² + k² standing for the complex square):
///   Rs = (η² + k² − 2η cos + cos²) / (η² + k² + 2η cos + cos²)
///   Rp = ((η² + k²) cos² − 2η cos + 1) / ((η² + k²) cos² + 2η cos + 1)
///   F  = (Rs + Rp) / 2
glm::vec3 fresnel_conductor(float cos_i, const glm::vec3& eta, const glm::vec3& k);

/// The course's microfacet material: a Cook-Torrance BRDF
///   f(wo, wi) = F(wi) · G(wo, wi) · D(h) / (4 (n·wo)(n·wi)),   h = normalize(wo + wi),
/// with D Beckmann's distribution of roughness alpha, F the conductor Fresnel above taken at
/// the angle of wi to the normal (as the course takes it), and G Smith's shadowing-masking,
/// G = 1 / (1 + Λ(wo) + Λ(wi)), with Walter et al.'s rational fit of Beckmann's Λ. It reflects
/// only (both directions above the surface) and samples the half vector from D, not the cosine.
class MicrofacetBsdf final : public Bsdf {
 public:
  MicrofacetBsdf() = default;
  MicrofacetBsdf(float alpha, const glm::vec3& eta, const glm::vec3& k);

  glm::vec3 f(const glm::vec3& wo, const glm::vec3& wi) const override;
  glm::vec3 sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const override;
  float pdf(const glm::vec3& wo, const glm::vec3& wi) const override;
  bool is_delta() const override { return false; }

  /// Beckmann's normal distribution D(h) = exp(−tan²θh / α²) / (π α² cos⁴θh), per unit solid
  /// angle of h, normalised so that ∫ D(h) cosθh dω = 1.
  float distribution(const glm::vec3& h) const;
  /// Smith's Λ for Beckmann (Walter et al. 2007's fit): a = 1 / (α tanθ),
  /// Λ = (1 − 1.259a + 0.396a²) / (3.535a + 2.181a²) for a < 1.6, else 0.
  float lambda(const glm::vec3& w) const;
  /// G(wo, wi) = 1 / (1 + Λ(wo) + Λ(wi)).
  float shadowing_masking(const glm::vec3& wo, const glm::vec3& wi) const;

 private:
  float alpha_ = 0.5f;
  glm::vec3 eta_{1.0f}, k_{0.0f};
};

}  // namespace pt
