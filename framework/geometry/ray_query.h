// The interface a lighting stage asks rays of: a brute-force loop (Part 1) or a BVH (Part 2).
#pragma once

#include "framework/geometry/surface_hit.h"
#include "framework/math/ray.h"

namespace pt {

/// Nearest-hit and any-hit queries against one scene. Lighting code takes a RayQuery, so its
/// tests can hand it brute force over three triangles and its users a BVH over a million.
class RayQuery {
 public:
  virtual ~RayQuery() = default;
  /// Nearest hit with ray.tmin < t < ray.tmax; on a hit, fills *hit and returns true.
  virtual bool intersect(const Ray& ray, SurfaceHit* hit) const = 0;
  /// Whether anything lies on the ray with tmin < t < tmax (a shadow ray).
  virtual bool occluded(const Ray& ray) const = 0;
};

}  // namespace pt
