// A ray: origin, direction and the open interval (tmin, tmax) of distances that count.
#pragma once

#include <glm/vec3.hpp>
#include <limits>

namespace pt {

/// A ray o + t·d. Only hits with tmin < t < tmax count; a nearest-hit query shrinks tmax as it
/// finds closer hits, so tmax doubles as "the best hit so far".
struct Ray {
  glm::vec3 o{0.0f};
  glm::vec3 d{0.0f, 0.0f, -1.0f};
  float tmin = 0.0f;
  float tmax = std::numeric_limits<float>::infinity();

  glm::vec3 at(float t) const { return o + t * d; }
};

}  // namespace pt
