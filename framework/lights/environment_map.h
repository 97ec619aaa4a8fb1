// Not needed for the assignment.
// An image-based infinite light: a latitude-longitude radiance map, sampled by its power.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/sampling/distribution.h"

namespace pt {

/// A lat-long map around +y (the course's convention): row 0 looks up (+y), the last row down;
/// column u = 0 faces −x and u grows with φ = atan2(z, −x) (direction_to_uv is the definition).
/// Sampled by a 2D piecewise-constant distribution over its pixels weighted by
/// luminance·sinθ, so bright pixels (the sun) get the samples and the poles are not oversampled.
class EnvironmentMap {
 public:
  /// Reads `path` through the image module (OpenImageIO). On failure returns false and says why
  /// in *error (naming the file and the problem).
  bool load(const std::string& path, std::string* error);
  /// A map from pixels already in memory (row-major RGB, top row first), for tests.
  void set_pixels(int width, int height, std::vector<glm::vec3> rgb);

  glm::vec3 radiance(const glm::vec3& dir) const;
  /// A direction with density *pdf per steradian (0 when the sample is unusable).
  glm::vec3 sample(glm::vec2 u, float* pdf) const;
  float pdf(const glm::vec3& dir) const;

  static glm::vec2 direction_to_uv(const glm::vec3& dir);
  static glm::vec3 uv_to_direction(glm::vec2 uv);

 private:
  void build_distribution();
  int width_ = 0, height_ = 0;
  std::vector<glm::vec3> pixels_;
  Distribution2D distribution_;
};

}  // namespace pt
