// Rays that leave a surface: started outside the hit point's error box, so that rounding never
// lets a ray hit the surface it leaves (and, towards a point, never reach into that point's box).
#pragma once

#include <glm/vec3.hpp>

#include "framework/geometry/surface_hit.h"
#include "framework/math/ray.h"

namespace pt {

/// A ray leaving `hit` in direction `w`, started just outside the hit point's error box on w's
/// side of the surface, so it cannot hit the surface it leaves. Its interval is (0, +inf).
///
/// The origin is offset_ray_origin(p, p_error, ng, w) (float_error.h): p moved along ng by
/// d = |ng|·p_error (the error box's extent along the normal), to w's side, each coordinate then
/// rounded one float further away from p.
Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& w);

/// The ray from `hit` to the point `p` (error bound `p_error`) that lies in direction `w` from
/// it, on a surface of normal `n` (zero for a point with no surface, a point light): it starts
/// outside the hit's error box and ends just short of p's (pushed back towards the hit), so it
/// meets neither the surface it leaves nor the one it aims at. An empty interval when nothing
/// lies between the two.
///
/// With o = spawn_ray(hit, w).o and the target q = offset_ray_origin(p, p_error, n, -w) (p itself
/// when n is zero): the direction is (q - o) / |q - o| and tmax = |q - o|·(1 - γ4), short of q by
/// more than the rounding of |q - o| (float_error.h's γn bounds n roundings).
Ray spawn_ray_to(const SurfaceHit& hit, const glm::vec3& w, const glm::vec3& p,
                 const glm::vec3& p_error, const glm::vec3& n);

}  // namespace pt
