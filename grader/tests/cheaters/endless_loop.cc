// Cheater (attacks the grader's time; replaces parts/1-raygen/triangle_intersect.cpp): never
// returns.
#include "parts/1-raygen/triangle_intersect.h"

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
  volatile unsigned long spin = 0;
  for (;;) spin = spin + 1;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
