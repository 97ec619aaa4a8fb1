// A ray: origin, direction and the open interval (tmin, tmax) of distances that count.
#pragma once

#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

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

/// Whether a ray can hit anything: a finite origin, a finite direction that is not zero, and an
/// interval with no NaN (tmax may be +inf). Every ray query answers any other ray with a miss, at
/// its entry: a NaN compares false everywhere, so a slab test would let such a ray into every box
/// of a tree, empty ones included.
inline bool is_traceable(const Ray& r) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(r.o[a]) || !std::isfinite(r.d[a])) return false;
  return (r.d.x != 0.0f || r.d.y != 0.0f || r.d.z != 0.0f) && !std::isnan(r.tmin) &&
         !std::isnan(r.tmax);
}

}  // namespace pt
