// BVH traversal: the student's two loops (nearest hit, any hit) and the leaf plumbing they call.
#include <algorithm>
#include <cmath>
#include <utility>

#include "pipeline/1-raygen/scene_intersect.h"
#include "parts/1-raygen/triangle_intersect.h"
#include "parts/2-bvh/bvh.h"
#include "framework/math/float_error.h"
#include "framework/student/todo.h"

namespace pt {

/// A nearest-hit query in flight. The answer is the smallest t any primitive reports for the
/// ray's own interval, the lower primitive index winning a tie: a definition that does not depend
/// on the order primitives are visited in, so the BVH, visiting them in its own order, gives
/// brute force's answer (Part1's intersect_triangle compares t·det with tmax·det, so whether a
/// hit an ulp short of tmax counts can depend on tmax's rounding: primitives are therefore judged
/// on the t they report, never on a shrunken tmax).
///
/// What shrinks is only the bound boxes and triangles are culled by: the best t stretched by
/// kHitDistanceSlack, so a rival an ulp or two nearer in another leaf is still compared. It costs
/// a few more box tests near ties, nothing else.
///
/// During the walk a triangle is only (primitive, t): the SurfaceHit (point, error bound,
/// normals, material) is made once, for the winner, after the walk.
struct Bvh::NearestState {
  explicit NearestState(const Ray& ray_) : ray(ray_), cull(ray_), box(ray_) {}
  const Ray& ray;
  Ray cull;  ///< the ray with tmax = the culling bound
  BoxRay box;
  uint32_t best = UINT32_MAX;  ///< primitive of the best hit, UINT32_MAX while there is none
  float best_t = 0.0f;
  /// Make every candidate's SurfaceHit as it is found, so one Part 1 refuses to shade is never
  /// the best (the rare second pass of intersect()).
  bool in_full = false;
  bool hit_made = false;  ///< `hit` is the best's SurfaceHit already (spheres; the second pass)
  SurfaceHit hit;
  /// A best triangle's t and barycentrics as its test reported them, from which intersect() makes
  /// its SurfaceHit without testing it a second time.
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

void Bvh::intersect_leaf(const BvhNode& leaf, NearestState* st) const {
  for (uint32_t i = leaf.offset, end = leaf.offset + leaf.count; i < end; ++i) {
    const uint32_t prim = order_[i];
    if (scene_.is_triangle(prim) && !st->in_full) {
      // The leaf's own copy of the corners is bit-identical to the scene's, so t is the very t
      // brute force's intersect_primitive reports.
      TriangleHit th;
      const TriangleCorners& c = corners_[i];
      if (intersect_triangle(st->cull, c.p0, c.p1, c.p2, &th) && st->beats_best(th.t, prim)) {
        st->take(th.t, prim, false);
        st->best_triangle = th;
      }
      continue;
    }
    SurfaceHit h;
    if (!intersect_primitive(scene_, prim, st->ray, &h) || !st->beats_best(h.t, prim)) continue;
    st->hit = h;
    st->take(h.t, prim, true);
  }
}

bool Bvh::leaf_occludes(const BvhNode& leaf, const Ray& ray) const {
  for (uint32_t i = leaf.offset, end = leaf.offset + leaf.count; i < end; ++i) {
    const uint32_t prim = order_[i];
    if (scene_.is_triangle(prim)) {
      TriangleHit th;
      const TriangleCorners& c = corners_[i];
      if (intersect_triangle(ray, c.p0, c.p1, c.p2, &th)) return true;
    } else if (primitive_occludes(scene_, prim, ray)) {
      return true;
    }
  }
  return false;
}

bool Bvh::intersect(const Ray& ray, SurfaceHit* hit) const {
  if (nodes_.empty()) return false;
  NearestState st(ray);
  traverse_nearest(&st);
  if (!st.found()) return false;
  if (st.hit_made) {
    *hit = st.hit;
    return true;
  }
  // The winner is a triangle (spheres are made as they are found): its t and barycentrics are
  // the ones brute force's intersect_primitive gets (the same corners; a nearer tmax changes
  // which hits count, not their values), so its SurfaceHit is made from them directly.
  if (triangle_surface_hit(scene_, st.best, st.best_triangle, hit)) return true;
  // Part 1 refuses to shade the winner (a triangle too thin in float to have a normal), so brute
  // force never saw it: walk again making each candidate in full, as brute force does.
  NearestState careful(ray);
  careful.in_full = true;
  traverse_nearest(&careful);
  if (!careful.found()) return false;
  *hit = careful.hit;
  return true;
}

void Bvh::traverse_nearest(NearestState* state) const {
  NearestState& st = *state;
  // BEGIN SOLUTION
  // Nodes still to visit, with the distance at which the ray enters them: a node that the ray
  // enters only beyond the best hit found since it was pushed is dropped unopened.
  struct Entry {
    uint32_t node;
    float t;
  };
  Entry stack[kMaxDepth];
  int top = 0;
  float t_root;
  if (!intersect_box(nodes_[0].bounds, st.box, st.cull.tmax, &t_root)) return;
  stack[top++] = {0, t_root};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t > st.cull.tmax) continue;
    uint32_t index = e.node;
    for (;;) {
      const BvhNode& node = nodes_[index];
      if (node.is_leaf()) {
        intersect_leaf(node, &st);
        break;
      }
      uint32_t near = index + 1, far = node.offset;
      float t_near, t_far;
      const bool hit_near = intersect_box(nodes_[near].bounds, st.box, st.cull.tmax, &t_near);
      const bool hit_far = intersect_box(nodes_[far].bounds, st.box, st.cull.tmax, &t_far);
      if (hit_near && hit_far) {
        if (t_far < t_near) std::swap(near, far), std::swap(t_near, t_far);
        stack[top++] = {far, t_far};
        index = near;
      } else if (hit_near || hit_far) {
        index = hit_near ? near : far;
      } else {
        break;
      }
    }
  }
  return;
  // END SOLUTION
  // STUDENT: keep a stack of nodes to visit, each with the distance at which the ray enters it.
  // Start with the root if intersect_box(root.bounds, st.box, st.cull.tmax, ...) says so. Pop
  // a node (skip it if it starts beyond st.cull.tmax, which shrinks as hits are found); at a leaf
  // call intersect_leaf(node, &st); at an interior node test both children (the first is
  // index + 1, the second node.offset) and go into the nearer one, pushing the other.
  // intersect() turns the best hit intersect_leaf kept into a SurfaceHit afterwards.
  PT_STUDENT_TODO("part 2", "Bvh::traverse_nearest");
  for (const BvhNode& node : nodes_)
    if (node.is_leaf()) intersect_leaf(node, &st);
}

bool Bvh::occluded(const Ray& ray) const {
  if (nodes_.empty()) return false;
  const BoxRay box(ray);
  // BEGIN SOLUTION
  // Order does not matter when any occluder will do: no distances kept, no sorting.
  uint32_t stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = nodes_[stack[--top]];
    float t;
    if (!intersect_box(node.bounds, box, ray.tmax, &t)) continue;
    if (node.is_leaf()) {
      if (leaf_occludes(node, ray)) return true;
    } else {
      stack[top++] = node.offset;
      stack[top++] = uint32_t(&node - nodes_.data()) + 1;
    }
  }
  return false;
  // END SOLUTION
  // STUDENT: the same walk as intersect, but return true at the first leaf where
  // leaf_occludes(node, ray) says so; no nearest-first order or distances are needed.
  PT_STUDENT_TODO("part 2", "Bvh::occluded");
  for (const BvhNode& node : nodes_)
    if (node.is_leaf() && leaf_occludes(node, ray)) return true;
  return false;
}

}  // namespace pt
