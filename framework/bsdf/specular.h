// Not needed for the assignment.
// Perfect specular BSDFs: the mirror and the smooth dielectric (glass) with exact Fresnel terms.
#pragma once

#include <glm/vec3.hpp>

#include "framework/bsdf/bsdf.h"

namespace pt {

/// Unpolarised Fresnel reflectance of a smooth dielectric boundary for light arriving under
/// cosine cos_i (> 0 on the side the normal points to) with eta = η_inside / η_outside. Returns 1
/// under total internal reflection.
float fresnel_dielectric(float cos_i, float eta);

/// The mirror reflection of w about the local normal (0, 0, 1).
inline glm::vec3 reflect_local(const glm::vec3& w) { return {-w.x, -w.y, w.z}; }

/// A perfect mirror: all light leaves in the reflected direction, scaled by `reflectance`.
class MirrorBsdf final : public Bsdf {
 public:
  explicit MirrorBsdf(const glm::vec3& reflectance = glm::vec3(1.0f)) : reflectance_(reflectance) {}
  glm::vec3 f(const glm::vec3&, const glm::vec3&) const override { return glm::vec3(0.0f); }
  glm::vec3 sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const override;
  float pdf(const glm::vec3&, const glm::vec3&) const override { return 0.0f; }
  bool is_delta() const override { return true; }

 private:
  glm::vec3 reflectance_;
};

/// Smooth glass: reflects with the Fresnel probability F and refracts otherwise (Snell's law),
/// choosing one of the two at random, so each sample's weight is reflectance or transmittance.
/// The normal's side (+z) is outside; radiance crossing into the denser side is scaled by
/// 1/η² (radiance is not invariant across a refractive boundary).
class GlassBsdf final : public Bsdf {
 public:
  GlassBsdf(const glm::vec3& reflectance = glm::vec3(1.0f),
            const glm::vec3& transmittance = glm::vec3(1.0f), float ior = 1.5f)
      : reflectance_(reflectance), transmittance_(transmittance), ior_(ior) {}
  glm::vec3 f(const glm::vec3&, const glm::vec3&) const override { return glm::vec3(0.0f); }
  glm::vec3 sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const override;
  float pdf(const glm::vec3&, const glm::vec3&) const override { return 0.0f; }
  bool is_delta() const override { return true; }

 private:
  glm::vec3 reflectance_, transmittance_;
  float ior_;
};

}  // namespace pt
