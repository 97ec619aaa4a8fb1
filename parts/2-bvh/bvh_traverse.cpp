// Part 2, step 3 (traversal): the student's two loops through the tree, Bvh::traverse_nearest
// (nearest hit) and Bvh::occluded (any hit); the leaf tests they call are given.
#include <utility>

#include "framework/student/todo.h"
#include "parts/2-bvh/bvh.h"

namespace pt {

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
  // STUDENT: traverse_nearest walks the tree so that every leaf that may hold a hit nearer than
  // the best so far goes through intersect_leaf(node, &st), which keeps the best hit and shrinks
  // st.cull.tmax; use st.cull.tmax as the far end of your box tests. What must hold
  // (docs/handout/part2.md step 3): brute force's nearest hit on every tree, including ones
  // dozens of levels deep; and few primitive tests per ray, as a walk that opens nearer boxes
  // first and none that start beyond st.cull.tmax makes. intersect() turns the best hit into a
  // SurfaceHit afterwards.
  PT_STUDENT_TODO("part 2", "Bvh::traverse_nearest");
  (void)st;  // no hit: the tree finds nothing until you write its walk
}

bool Bvh::occluded(const Ray& ray) const {
  if (nodes_.empty() || !is_traceable(ray)) return false;
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
  // STUDENT: return whether anything lies on the ray within its interval (leaf_occludes(node,
  // ray) tests a leaf's primitives); any occluder will do, found in any order.
  PT_STUDENT_TODO("part 2", "Bvh::occluded");
  (void)box;
  return false;
}

}  // namespace pt
