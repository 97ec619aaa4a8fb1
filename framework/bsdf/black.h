// Not needed for the assignment.
// The BSDF of a surface that reflects nothing: the course's emitters (CGL emission materials).
#pragma once

#include <glm/vec3.hpp>

#include "framework/bsdf/bsdf.h"

namespace pt {

/// Scatters no light at all: f, pdf and every sample are zero. The course's loader gives an
/// emission material this BSDF, so its light panels glow without also reflecting the room.
class BlackBsdf final : public Bsdf {
 public:
  glm::vec3 f(const glm::vec3&, const glm::vec3&) const override { return glm::vec3(0.0f); }
  glm::vec3 sample_f(const glm::vec3&, glm::vec2, glm::vec3* wi, float* pdf) const override {
    *wi = glm::vec3(0.0f, 0.0f, 1.0f);
    *pdf = 0.0f;
    return glm::vec3(0.0f);
  }
  float pdf(const glm::vec3&, const glm::vec3&) const override { return 0.0f; }
  bool is_delta() const override { return false; }
};

}  // namespace pt
