// The interface every BSDF offers the integrators: evaluate, sample, and the density of a sample.
//
// Directions are in the local shading frame (z along the shading normal), both pointing away from
// the surface: wo towards the viewer, wi towards the light.
//
// The sampling convention, stated here once for every BSDF and every caller: sample_f returns
// the BSDF value f(wo, wi) itself, not the estimator weight, and sets the density *pdf of the
// wi it drew. The caller forms the weight f·|cos θi| / pdf. (For a delta BSDF, f carries the
// delta's scale divided by |cos θi|, so that the same weight formula holds.)
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pt {

/// A scattering model. f and pdf are densities over directions; a specular (delta) BSDF has
/// f = pdf = 0 for any given pair and scatters only through sample_f.
class Bsdf {
 public:
  virtual ~Bsdf() = default;
  /// The BSDF value for the pair (wo, wi).
  virtual glm::vec3 f(const glm::vec3& wo, const glm::vec3& wi) const = 0;
  /// Draws wi given wo from the uniform point u, sets *pdf to its density (for a delta BSDF, the
  /// probability of the discrete choice made) and returns f(wo, wi): the value, not the weight
  /// f·|cos θi| / pdf (the convention above). Returns zero with *pdf = 0 when it draws nothing.
  virtual glm::vec3 sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const = 0;
  /// Density with which sample_f would draw wi given wo (0 for delta BSDFs).
  virtual float pdf(const glm::vec3& wo, const glm::vec3& wi) const = 0;
  /// Whether it scatters only into a few discrete directions (light sampling cannot reach them).
  virtual bool is_delta() const = 0;
};

}  // namespace pt
