// An orthonormal frame about a unit vector, for turning local (z-up) directions into world ones.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace pt {

/// Orthonormal basis (s, t, n). Built without branches on the normal's direction
/// (Duff et al. 2017, "Building an orthonormal basis, revisited"), so it is continuous and
/// never divides by a near-zero component.
struct Frame {
  glm::vec3 s, t, n;

  explicit Frame(const glm::vec3& normal) : n(normal) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    s = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = glm::vec3(b, sign + n.y * n.y * a, -n.y);
  }

  glm::vec3 to_world(const glm::vec3& v) const { return v.x * s + v.y * t + v.z * n; }
  glm::vec3 to_local(const glm::vec3& v) const {
    return glm::vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n));
  }
};

}  // namespace pt
