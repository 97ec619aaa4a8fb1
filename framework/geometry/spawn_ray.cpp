// Not needed for the assignment: the definitions of framework/geometry/spawn_ray.h.
#include "framework/geometry/spawn_ray.h"

#include <limits>

#include <glm/geometric.hpp>

#include "framework/math/float_error.h"

namespace pt {

Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& w) {
  Ray r;
  r.o = offset_ray_origin(hit.p, hit.p_error, hit.ng, w);
  r.d = w;
  r.tmin = 0.0f;
  r.tmax = std::numeric_limits<float>::infinity();
  return r;
}

Ray spawn_ray_to(const SurfaceHit& hit, const glm::vec3& w, const glm::vec3& p,
                 const glm::vec3& p_error, const glm::vec3& n) {
  Ray r = spawn_ray(hit, w);
  glm::vec3 target = p;
  if (n != glm::vec3(0.0f)) target = offset_ray_origin(p, p_error, n, -w);
  glm::vec3 d = target - r.o;
  float len = glm::length(d);
  if (!(len > 0.0f)) {
    r.tmax = 0.0f;  // nothing between: the empty interval is never occluded
    return r;
  }
  r.d = d / len;
  // Stop short of the target by the rounding of its distance, so the end never reaches back
  // into the target's error box.
  r.tmax = len * (1.0f - gamma(4));
  return r;
}

}  // namespace pt
