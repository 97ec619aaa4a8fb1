// Part 2's probe: each graded function of Part 2, recorded as the test calls it (record.h).
#include "grader/judge/record.h"
#include "grader/judge/wrap.h"
#include "parts/2-bvh/bvh.h"
#include "parts/2-bvh/bvh_split.h"
#include "parts/2-bvh/ray_box.h"

#define INTERSECT_BOX "_ZN2pt13intersect_boxERKNS_7Bounds3ERKNS_6BoxRayEfPf"
#define MIDPOINT_SPLIT "_ZN2pt14midpoint_splitERKNS_7Bounds3E"
#define BEST_SAH_SPLIT "_ZN2pt14best_sah_splitEPKNS_6SahBinEifRKNS_8SahCostsE"
#define BVH_TRAVERSE_NEAREST "_ZNK2pt3Bvh16traverse_nearestEPNS0_12NearestStateE"
#define BVH_OCCLUDED "_ZNK2pt3Bvh8occludedERKNS_3RayE"
#define INTERSECT_LEAF "_ZN2pt14intersect_leafERKNS_5SceneERKNS_14LeafPrimitivesEjjPNS_15NearestHitQueryE"
#define LEAF_OCCLUDES "_ZN2pt13leaf_occludesERKNS_5SceneERKNS_14LeafPrimitivesEjjRKNS_3RayE"

namespace pt::judge {
namespace real {
bool intersect_box(const Bounds3&, const BoxRay&, float, float*) PT_REAL(INTERSECT_BOX);
MidpointSplit midpoint_split(const Bounds3&) PT_REAL(MIDPOINT_SPLIT);
SahSplit best_sah_split(const SahBin*, int, float, const SahCosts&) PT_REAL(BEST_SAH_SPLIT);
// Members: the object is the first argument. The walk's state is private to Bvh; its first base,
// at the same address, is the NearestHitQuery the walk fills.
void bvh_traverse_nearest(const Bvh*, NearestHitQuery*) PT_REAL(BVH_TRAVERSE_NEAREST);
bool bvh_occluded(const Bvh*, const Ray&) PT_REAL(BVH_OCCLUDED);
// The given leaf tests the walks call: each is a callback of the walk, which the judge answers
// by testing the same leaf itself.
void intersect_leaf(const Scene&, const LeafPrimitives&, uint32_t, uint32_t, NearestHitQuery*)
    PT_REAL(INTERSECT_LEAF);
bool leaf_occludes(const Scene&, const LeafPrimitives&, uint32_t, uint32_t, const Ray&)
    PT_REAL(LEAF_OCCLUDES);
}  // namespace real

bool wrap_intersect_box(const Bounds3&, const BoxRay&, float, float*) PT_WRAP(INTERSECT_BOX);
bool wrap_intersect_box(const Bounds3& box, const BoxRay& ray, float tmax, float* t_entry) {
  ProbeCall call(Fn::intersect_box);
  bool met = real::intersect_box(box, ray, tmax, t_entry);
  call.out.put(uint8_t(met));
  call.out.put(uint8_t(t_entry != nullptr));
  if (t_entry) call.out.put(*t_entry);
  call.returned();
  return met;
}

MidpointSplit wrap_midpoint_split(const Bounds3&) PT_WRAP(MIDPOINT_SPLIT);
MidpointSplit wrap_midpoint_split(const Bounds3& centroids) {
  ProbeCall call(Fn::midpoint_split);
  MidpointSplit s = real::midpoint_split(centroids);
  call.out.put(s);
  call.returned();
  return s;
}

SahSplit wrap_best_sah_split(const SahBin*, int, float, const SahCosts&) PT_WRAP(BEST_SAH_SPLIT);
SahSplit wrap_best_sah_split(const SahBin* bins, int count, float area, const SahCosts& costs) {
  ProbeCall call(Fn::best_sah_split);
  SahSplit s = real::best_sah_split(bins, count, area, costs);
  call.out.put(s);
  call.returned();
  return s;
}

void wrap_bvh_traverse_nearest(const Bvh*, NearestHitQuery*) PT_WRAP(BVH_TRAVERSE_NEAREST);
void wrap_bvh_traverse_nearest(const Bvh* bvh, NearestHitQuery* q) {
  ProbeCall call(Fn::bvh_traverse_nearest);
  real::bvh_traverse_nearest(bvh, q);
  // What Bvh::intersect reads afterwards; the ray itself is the caller's.
  call.out.put(q->cull);
  call.out.put(q->best);
  call.out.put(q->best_t);
  call.out.put(uint8_t(q->in_full));
  call.out.put(uint8_t(q->hit_made));
  call.out.put(q->hit);
  call.out.put(q->best_triangle);
  call.returned();
}

bool wrap_bvh_occluded(const Bvh*, const Ray&) PT_WRAP(BVH_OCCLUDED);
bool wrap_bvh_occluded(const Bvh* bvh, const Ray& ray) {
  ProbeCall call(Fn::bvh_occluded);
  bool blocked = real::bvh_occluded(bvh, ray);
  call.out.put(uint8_t(blocked));
  call.returned();
  return blocked;
}

// A leaf test is named by its leaf's primitives in the tree's order: the judge refuses a range
// that is not one leaf of the tree.
void wrap_intersect_leaf(const Scene&, const LeafPrimitives&, uint32_t, uint32_t, NearestHitQuery*)
    PT_WRAP(INTERSECT_LEAF);
void wrap_intersect_leaf(const Scene& scene, const LeafPrimitives& leaves, uint32_t first,
                         uint32_t count, NearestHitQuery* q) {
  ProbeCallback test(Fn::bvh_traverse_nearest, kLeafTest);
  test.args.put(first);
  test.args.put(count);
  test.begin();
  real::intersect_leaf(scene, leaves, first, count, q);
  test.answer.put(q->best);
  test.answer.put(q->best_t);
  test.answer.put(q->cull.tmax);
  test.end();
}

bool wrap_leaf_occludes(const Scene&, const LeafPrimitives&, uint32_t, uint32_t, const Ray&)
    PT_WRAP(LEAF_OCCLUDES);
bool wrap_leaf_occludes(const Scene& scene, const LeafPrimitives& leaves, uint32_t first,
                        uint32_t count, const Ray& ray) {
  ProbeCallback test(Fn::bvh_occluded, kLeafTest);
  test.args.put(first);
  test.args.put(count);
  test.args.put(ray);
  test.begin();
  const bool blocked = real::leaf_occludes(scene, leaves, first, count, ray);
  test.answer.put(uint8_t(blocked));
  test.end();
  return blocked;
}

}  // namespace pt::judge
