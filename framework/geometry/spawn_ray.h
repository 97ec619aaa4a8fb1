// Rays that leave a surface: started outside the hit point's error box, so that rounding never
// lets a ray hit the surface it leaves (and, towards a point, never reach into that point's box).
#pragma once

#include <glm/vec3.hpp>

#include "framework/geometry/surface_hit.h"
#include "framework/math/ray.h"

namespace pt {

/// A ray leaving `hit` in direction `w`, started just outside the hit point's error box on w's
/// side of the surface, so it cannot hit the surface it leaves. Its interval is (0, +inf).
Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& w);

/// The ray from `hit` to the point `p` (error bound `p_error`) that lies in direction `w` from
/// it, on a surface of normal `n` (zero for a point with no surface, a point light): it starts
/// outside the hit's error box and ends just short of p's (pushed back towards the hit), so it
/// meets neither the surface it leaves nor the one it aims at. An empty interval when nothing
/// lies between the two.
Ray spawn_ray_to(const SurfaceHit& hit, const glm::vec3& w, const glm::vec3& p,
                 const glm::vec3& p_error, const glm::vec3& n);

/// spawn_ray written one glm operation at a time: its definition, as spawn_ray_to_portable is
/// spawn_ray_to's.
Ray spawn_ray_portable(const SurfaceHit& hit, const glm::vec3& w);

/// spawn_ray_to written one glm operation at a time: its definition. spawn_ray_to does the same
/// operations in SIMD lanes where the build has them (every shadow ray comes through it) and
/// must give these bits; the tests hold it to that.
Ray spawn_ray_to_portable(const SurfaceHit& hit, const glm::vec3& w, const glm::vec3& p,
                          const glm::vec3& p_error, const glm::vec3& n);

}  // namespace pt
