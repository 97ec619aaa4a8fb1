// Given code on Part 1: a nearest-hit query in flight through a tree's leaves, the state the
// leaf tests keep for the student's traversal (Part 2) and the wide BVH alike.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "framework/geometry/surface_hit.h"
#include "framework/math/float_error.h"
#include "framework/math/ray.h"

namespace pt {

/// How far past the nearest hit so far a nearest-hit traversal still looks: a hit's reported t
/// and a box's entry distance each stray from exact by a few ulps (unless the ray grazes the
/// surface), so a rival an ulp nearer in another box must not be culled before it is compared.
inline constexpr float kHitDistanceSlack = 1.0f + 2.0f * gamma(16);

/// A nearest-hit query in flight. The answer is the smallest t any primitive reports for the
/// ray's own interval, the lower primitive index winning a tie: a definition that does not depend
/// on the order primitives are visited in, so a tree, visiting them in its own order, gives
/// brute force's answer (Part 1's intersect_triangle compares t·det with tmax·det, so whether a
/// hit an ulp short of tmax counts can depend on tmax's rounding: primitives are therefore judged
/// on the t they report, never on a shrunken tmax).
///
/// What shrinks is only the bound boxes and triangles are culled by: the best t stretched by
/// kHitDistanceSlack, so a rival an ulp or two nearer in another leaf is still compared. It costs
/// a few more box tests near ties, nothing else.
///
/// During the walk a triangle is only (primitive, t): the SurfaceHit (point, error bound,
/// normals, material) is made once, for the winner, after the walk.
struct NearestHitQuery {
  explicit NearestHitQuery(const Ray& ray_) : ray(ray_), cull(ray_) {}
  const Ray& ray;
  Ray cull;  ///< the ray with tmax = the culling bound
  uint32_t best = UINT32_MAX;  ///< primitive of the best hit, UINT32_MAX while there is none
  float best_t = 0.0f;
  /// Make every candidate's SurfaceHit as it is found, so one Part 1 refuses to shade is never
  /// the best (the rare second pass of a full intersect).
  bool in_full = false;
  bool hit_made = false;  ///< `hit` is the best's SurfaceHit already (spheres; the second pass)
  SurfaceHit hit;
  /// A best triangle's t and barycentrics as its test reported them, from which the SurfaceHit
  /// is made without testing it a second time.
  TriangleHit best_triangle;

  bool found() const { return best != UINT32_MAX; }
  bool beats_best(float t, uint32_t prim) const {
    return !found() || t < best_t || (t == best_t && prim < best);
  }
  void take(float t, uint32_t prim, bool made) {
    best = prim;
    best_t = t;
    hit_made = made;
    cull.tmax = std::min(ray.tmax, t + std::abs(t) * (kHitDistanceSlack - 1.0f));
  }
};

}  // namespace pt
