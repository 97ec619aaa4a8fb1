// The framework's spawn_ray and spawn_ray_to (framework/geometry/spawn_ray.h) in SIMD lanes: the
// same operations in the same order, so the same bits (lane_rays_test holds them to that), for
// the shadow rays of the instructor's build.
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#pragma once

#include <glm/vec3.hpp>

#include "framework/geometry/spawn_ray.h"
#include "framework/geometry/surface_hit.h"
#include "framework/math/ray.h"

namespace pt {

/// spawn_ray(hit, w), bit for bit.
Ray spawn_ray_in_lanes(const SurfaceHit& hit, const glm::vec3& w);

/// spawn_ray_to(hit, w, p, p_error, n), bit for bit.
Ray spawn_ray_to_in_lanes(const SurfaceHit& hit, const glm::vec3& w, const glm::vec3& p,
                          const glm::vec3& p_error, const glm::vec3& n);

}  // namespace pt
