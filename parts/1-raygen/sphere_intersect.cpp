// Part 1, step 4 (sphere): intersect_sphere.
#include "parts/1-raygen/sphere_intersect.h"

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "framework/student/todo.h"

namespace pt {

bool intersect_sphere(const Ray& ray, const Sphere& sphere, float* t) {
  // BEGIN SOLUTION
  // |f + t d|^2 = r^2 with f = o - c: a t^2 + 2 h t + c = 0, with h the half of the usual b.
  const glm::vec3 f = ray.o - sphere.center;
  const float a = glm::dot(ray.d, ray.d);
  if (!(a > 0.0f)) return false;
  const float h = glm::dot(f, ray.d);
  const float r = sphere.radius;
  const float c = glm::dot(f, f) - r * r;

  // h^2 - a c = a (r^2 - |v|^2), v the centre's offset from the ray's closest point. Computing it
  // from v, as (r - |v|)(r + |v|), avoids subtracting two huge, nearly equal squares.
  const glm::vec3 v = f - (h / a) * ray.d;
  const float dist = glm::length(v);
  const float disc = a * ((r - dist) * (r + dist));
  if (disc < 0.0f) return false;

  // Add only quantities of the same sign; the second root comes from the product of the roots.
  const float q = -(h + std::copysign(std::sqrt(disc), h));
  float t0 = q / a;
  float t1 = (q != 0.0f) ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > ray.tmin && t0 < ray.tmax) {
    *t = t0;
    return true;
  }
  if (t1 > ray.tmin && t1 < ray.tmax) {
    *t = t1;
    return true;
  }
  return false;
  // END SOLUTION
  // STUDENT: set *t to the nearest t with tmin < t < tmax at which the ray meets the sphere's
  // surface and return true, else return false. Both roots count (a ray from inside hits the far
  // side), and the direction need not be unit length. The roots must agree with exact arithmetic
  // within a small relative error for far spheres, near-tangent rays and origins on the surface,
  // where the school formula loses its digits (docs/handout/part1.md step 4 says where to read).
  PT_STUDENT_TODO("part 1", "intersect_sphere");
  (void)ray, (void)sphere, (void)t;
  return false;
}

}  // namespace pt
