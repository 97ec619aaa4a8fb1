#include "1-raygen/triangle_intersect.h"

#include "student/todo.h"

namespace pt {

bool intersect_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                        const glm::vec3& p2, TriangleHit* hit) {
  // BEGIN SOLUTION
  // END SOLUTION
  // STUDENT: move the ray origin to (0,0,0) and shear the triangle so that the ray runs along +z,
  // compute the three edge functions in 2D (recomputing them in double when one is exactly
  // zero), reject on mixed signs or a zero determinant, and only then divide to get t and the
  // barycentric coordinates. Check tmin < t < tmax before filling *hit.
  PT_STUDENT_TODO("part 1", "intersect_triangle");
  (void)ray, (void)p0, (void)p1, (void)p2, (void)hit;
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit& hit, const glm::vec3& n0, const glm::vec3& n1,
                             const glm::vec3& n2) {
  // BEGIN SOLUTION
  // END SOLUTION
  // STUDENT: weigh each corner normal by its barycentric coordinate and normalise the sum.
  PT_STUDENT_TODO("part 1", "interpolate_normal");
  (void)hit, (void)n1, (void)n2;
  return n0;
}

}  // namespace pt
