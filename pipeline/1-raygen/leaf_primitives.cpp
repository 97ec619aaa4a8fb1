// Not needed for the assignment: the definitions of pipeline/1-raygen/leaf_primitives.h.
#include "pipeline/1-raygen/leaf_primitives.h"

#include <utility>

#include "parts/1-raygen/triangle_intersect.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt {

LeafPrimitives::LeafPrimitives(const Scene& scene, std::vector<uint32_t> order_)
    : order(std::move(order_)), corners(order.size()) {
  for (size_t i = 0; i < order.size(); ++i) {
    const uint32_t p = order[i];
    if (scene.is_triangle(p)) {
      const Triangle& t = scene.triangles[p];
      corners[i] = {scene.positions[t.v[0]], scene.positions[t.v[1]], scene.positions[t.v[2]]};
    }
  }
}

void intersect_leaf(const Scene& scene, const LeafPrimitives& leaves, uint32_t first,
                    uint32_t count, NearestHitQuery* st) {
  for (uint32_t i = first, end = first + count; i < end; ++i) {
    const uint32_t prim = leaves.order[i];
    if (scene.is_triangle(prim) && !st->in_full) {
      // The leaf's own copy of the corners is bit-identical to the scene's, so t is the very t
      // brute force's intersect_primitive reports.
      TriangleHit th;
      const LeafPrimitives::TriangleCorners& c = leaves.corners[i];
      if (intersect_triangle(st->cull, c.p0, c.p1, c.p2, &th) && st->beats_best(th.t, prim)) {
        st->take(th.t, prim, false);
        st->best_triangle = th;
      }
      continue;
    }
    SurfaceHit h;
    if (!intersect_primitive(scene, prim, st->ray, &h) || !st->beats_best(h.t, prim)) continue;
    st->hit = h;
    st->take(h.t, prim, true);
  }
}

bool leaf_occludes(const Scene& scene, const LeafPrimitives& leaves, uint32_t first,
                   uint32_t count, const Ray& ray) {
  for (uint32_t i = first, end = first + count; i < end; ++i) {
    const uint32_t prim = leaves.order[i];
    if (scene.is_triangle(prim)) {
      TriangleHit th;
      const LeafPrimitives::TriangleCorners& c = leaves.corners[i];
      if (intersect_triangle(ray, c.p0, c.p1, c.p2, &th)) return true;
    } else if (primitive_occludes(scene, prim, ray)) {
      return true;
    }
  }
  return false;
}

}  // namespace pt
