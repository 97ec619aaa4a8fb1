// Part 3, step 1 (diffuse_bsdf): the diffuse (Lambertian) BSDF, which scatters light equally in
// every direction.
#pragma once

#include <glm/vec3.hpp>

#include "framework/bsdf/bsdf.h"

namespace pt {

/// Step 1 (diffuse_bsdf).
/// A Lambertian reflector of albedo ρ (per channel): f = ρ/π above the surface (z > 0), zero
/// below. Sampled by cosine-weighted directions, whose density is cosθ/π.
class DiffuseBsdf final : public Bsdf {
 public:
  explicit DiffuseBsdf(const glm::vec3& albedo = glm::vec3(0.8f)) : albedo_(albedo) {}
  glm::vec3 f(const glm::vec3& wo, const glm::vec3& wi) const override;
  glm::vec3 sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const override;
  float pdf(const glm::vec3& wo, const glm::vec3& wi) const override;
  bool is_delta() const override { return false; }
  const glm::vec3& albedo() const { return albedo_; }

 private:
  glm::vec3 albedo_;
};

}  // namespace pt
