#include "1-raygen/sphere_intersect.h"

#include "student/todo.h"

namespace pt {

bool intersect_sphere(const Ray& ray, const Sphere& sphere, float* t) {
  // BEGIN SOLUTION
  // END SOLUTION
  // STUDENT: solve |o + t d - c|^2 = r^2 for t. Compute the discriminant from the distance of the
  // ray to the centre (not b^2 - 4ac, which cancels), take q = -(b + sign(b) sqrt(disc)) / 2 and
  // the roots q/a and c/q, and return the nearer root inside (tmin, tmax).
  PT_STUDENT_TODO("part 1", "intersect_sphere");
  (void)ray, (void)sphere, (void)t;
  return false;
}

}  // namespace pt
