// Part 2, step 1 (ray_box): whether a ray passes through an axis-aligned box, conservatively.
#pragma once

#include <glm/vec3.hpp>

#include "framework/math/bounds.h"
#include "framework/math/float_error.h"
#include "framework/math/ray.h"

namespace pt {

/// A ray prepared once for many box tests: the reciprocal of its direction, so a slab test costs
/// multiplications only. A zero component gives an infinite reciprocal, which the slab test
/// handles (that slab is then either everything or nothing).
struct BoxRay {
  glm::vec3 o{0.0f};
  glm::vec3 inv_d{0.0f};
  float tmin = 0.0f;

  BoxRay() = default;
  explicit BoxRay(const Ray& ray) : o(ray.o), inv_d(1.0f / ray.d), tmin(ray.tmin) {}
};

/// Step 1 (ray_box).
/// Whether the ray meets `box` at some distance in [ray.tmin, tmax]; on success *t_entry is where
/// it enters (clamped to tmin), which lets a traversal visit the nearer of two boxes first.
/// Conservative: each slab's far distance is enlarged and its near distance reduced by their
/// rounding error (Ize 2013), so a ray that meets a point of the box at exact distance s in the
/// interval is never turned away by rounding, and *t_entry <= s, even through a flat box or along
/// a box face. A slab the ray runs inside of (0 · inf, NaN) narrows nothing.
bool intersect_box(const Bounds3& box, const BoxRay& ray, float tmax, float* t_entry);

}  // namespace pt
