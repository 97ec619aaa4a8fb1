// Cheater (attacks the triangle's steps; replaces parts/1-raygen/triangle_intersect.cpp): leaves
// with _Exit(0), which skips even atexit handlers.
#include "parts/1-raygen/triangle_intersect.h"

#include <cstdlib>

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) { std::_Exit(0); }

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
