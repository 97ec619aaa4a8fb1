// Axis-aligned bounding boxes.
#pragma once

#include <algorithm>
#include <limits>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace pt {

/// An axis-aligned box [lo, hi]. The default box is empty (lo = +inf, hi = -inf), so growing it
/// by anything gives that thing.
struct Bounds3 {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void grow(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Bounds3& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  glm::vec3 extent() const { return empty() ? glm::vec3(0.0f) : hi - lo; }
  glm::vec3 center() const { return 0.5f * (lo + hi); }
  float surface_area() const {
    glm::vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  int longest_axis() const {
    glm::vec3 e = extent();
    return (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
  }
};

}  // namespace pt
