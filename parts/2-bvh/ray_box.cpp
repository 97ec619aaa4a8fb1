// Part 2, step 1 (ray_box): intersect_box.
#include "parts/2-bvh/ray_box.h"

#include <cmath>

#include "framework/math/float_error.h"
#include "framework/student/todo.h"

namespace pt {

bool intersect_box(const Bounds3& box, const BoxRay& ray, float tmax, float* t_entry) {
  // BEGIN SOLUTION
  // Each distance is within γ(3) of exact (the reciprocal, the difference, the product): stretching
  // the far one up and the near one down by 2·γ(3) makes the interval contain the exact one
  // (Ize 2013; pbrt-v3, 3.9.2), so neither the hit test nor the entry distance a traversal culls
  // by can turn away a point that is in the box.
  constexpr float kFarScale = 1.0f + 2.0f * gamma(3);
  constexpr float kNearScale = 1.0f - 2.0f * gamma(3);
  float t0 = ray.tmin, t1 = tmax;
  for (int a = 0; a < 3; ++a) {
    // Near and far planes chosen by the direction's sign, not by comparing the distances: for a
    // -0 component with the origin on a plane, that distance is 0 · -inf = NaN, and a comparison
    // would pair the NaN with the other plane's -inf and turn away a ray running along the face.
    const bool negative = std::signbit(ray.inv_d[a]);
    float tn = ((negative ? box.hi[a] : box.lo[a]) - ray.o[a]) * ray.inv_d[a];
    float tf = ((negative ? box.lo[a] : box.hi[a]) - ray.o[a]) * ray.inv_d[a];
    tf *= tf > 0.0f ? kFarScale : kNearScale;
    tn *= tn > 0.0f ? kNearScale : kFarScale;
    // Written so that a NaN distance (origin on the slab plane, direction parallel) keeps t0/t1.
    t0 = tn > t0 ? tn : t0;
    t1 = tf < t1 ? tf : t1;
  }
  *t_entry = t0;
  return t0 <= t1;
  // END SOLUTION
  // STUDENT: return whether the ray meets the box at some distance in [ray.tmin, tmax], and on
  // a hit set *t_entry to the distance at which it enters (tmin if it starts inside), or less by
  // rounding: the traversal visits nearer boxes first by it and skips those that start beyond
  // its best hit. What must hold (each is a check, docs/handout/part2.md step 1): a box the ray
  // truly meets is never rejected because of rounding, and *t_entry is never beyond the true
  // entry; each slab's near and far planes follow the sign of the direction's component (-0
  // counts as negative); a ray along a face, in a flat box or with a zero direction component
  // counts where it touches the box; a box before tmin or beyond tmax, or well beside the ray, is
  // missed.
  PT_STUDENT_TODO("part 2", "intersect_box");
  (void)box, (void)ray, (void)tmax;
  *t_entry = 0.0f;
  return true;
}

}  // namespace pt
