// Part 2, step 3 (traversal): a bounding volume hierarchy over a scene's primitives, and the ray
// queries through it. The student writes Bvh::traverse_nearest and Bvh::occluded
// (bvh_traverse.cpp); the construction and Bvh::intersect are given (pipeline/2-bvh/), and so are
// the leaf tests they call (pipeline/1-raygen/leaf_primitives.h).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/scene/scene.h"
#include "parts/2-bvh/bvh_split.h"
#include "parts/2-bvh/ray_box.h"
#include "pipeline/1-raygen/leaf_primitives.h"
#include "pipeline/1-raygen/nearest_hit_query.h"

namespace pt {

namespace test {
struct LeafLog;
/// Given: writes one leaf test into *log (framework/testing/leaf_log.h).
void note_leaf_test(LeafLog* log, uint32_t node, uint32_t count, float tmax);
}  // namespace test

/// How to build a BVH.
struct BvhOptions {
  BvhSplitMethod split = BvhSplitMethod::sah;
  /// The most primitives a leaf may hold (1 .. kMaxLeafSize): a node with more is always split.
  /// The midpoint split splits every node down to this size; the SAH also keeps a smaller node
  /// whole when testing its primitives costs less than the best split it finds.
  int max_leaf_size = 4;
  int sah_bins = 16;      ///< centroid bins per axis (2 .. kMaxSahBins)
  SahCosts costs;  ///< the SAH's weights, also used for BvhStats::sah_cost
};

/// One node of the flattened tree, 32 bytes, two to a cache line. Nodes are stored depth first:
/// an interior node's first child is the next node, so only the second child's index is kept.
struct alignas(32) BvhNode {
  Bounds3 bounds;
  uint32_t offset = 0;  ///< leaf: first entry in the primitive order; interior: second child
  uint16_t count = 0;   ///< primitives in a leaf; 0 for an interior node
  uint8_t axis = 0;     ///< interior: the split axis (for inspection)
  uint8_t pad = 0;

  bool is_leaf() const { return count > 0; }
};

/// What a build made, for `pathtracer --info` and for bench. SAH cost uses the build's costs,
/// relative to the root box: the expected work of a random ray that hits the root.
struct BvhStats {
  uint32_t primitives = 0;
  uint32_t nodes = 0;
  uint32_t leaves = 0;
  uint32_t depth = 0;          ///< longest root-to-leaf path, in edges
  uint32_t max_leaf_size = 0;  ///< largest leaf actually made
  double mean_leaf_size = 0.0;
  double sah_cost = 0.0;
  double build_ms = 0.0;
  BvhSplitMethod split = BvhSplitMethod::sah;
};

/// A binary BVH over every primitive of a scene (triangles and spheres), answering the same
/// queries as BruteForce with the same answers: the nearest hit (ties go to the lower primitive
/// index, as brute force's order gives them) and whether anything occludes a ray. The scene must
/// outlive the BVH. Leaves keep copies of their triangles' corners (LeafPrimitives), so a leaf's
/// triangles are read from one contiguous block.
class Bvh final : public RayQuery {
 public:
  explicit Bvh(const Scene& scene, const BvhOptions& options = {});

  bool intersect(const Ray& ray, SurfaceHit* hit) const override;
  /// Step 3 (traversal), the student's other walk.
  /// Whether anything lies on `ray` within its interval, as brute force answers: any leaf whose
  /// leaf_occludes says so will do, in any order; "nothing blocks" only after every leaf the ray
  /// meets has gone through leaf_occludes.
  bool occluded(const Ray& ray) const override;

  const BvhStats& stats() const { return stats_; }
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  /// Primitive indices in leaf order: leaf node n holds order()[n.offset .. n.offset + n.count).
  const std::vector<uint32_t>& order() const { return leaves_.order; }

  /// Counts, into *counter, every primitive a leaf test of this tree tests from now on (null:
  /// stop). Given code, for the checks of what a tree saves (Part 2's traversal tests compare the
  /// count per ray with what a good walk of the same tree needs); a render never sets it. Not
  /// for a tree shared between threads while it counts.
  void count_primitive_tests(uint64_t* counter) { primitive_tests_ = counter; }
  /// Writes into *log every leaf test of this tree from now on (null: stop): the node, and the
  /// ray's far end at the test. Given code, for Part 2's traversal tests, which check from it
  /// that a walk opens every leaf that may hold a nearer hit and none that cannot.
  void log_leaf_tests(test::LeafLog* log) { leaf_log_ = log; }

  static constexpr int kMaxLeafSize = 255;
  /// Deeper than this the build splits by count, so no traversal stack can overflow.
  static constexpr int kMaxDepth = 96;

 private:
  /// A nearest-hit query through this tree: the leaf tests' state (pipeline/1-raygen), and the
  /// ray prepared for box tests.
  struct NearestState : NearestHitQuery {
    explicit NearestState(const Ray& ray_) : NearestHitQuery(ray_), box(ray_) {}
    BoxRay box;
  };

  /// Step 3 (traversal).
  /// The student's nearest-first walk: visits leaves through intersect_leaf until no node left
  /// can hold a nearer hit. intersect() makes the SurfaceHit of the winner afterwards.
  void traverse_nearest(NearestState* state) const;
  /// The leaf tests, for a node of this tree.
  void intersect_leaf(const BvhNode& leaf, NearestState* state) const {
    if (primitive_tests_) *primitive_tests_ += leaf.count;
    if (leaf_log_) test::note_leaf_test(leaf_log_, index_of(leaf), leaf.count, state->cull.tmax);
    pt::intersect_leaf(scene_, leaves_, leaf.offset, leaf.count, state);
  }
  bool leaf_occludes(const BvhNode& leaf, const Ray& ray) const {
    if (primitive_tests_) *primitive_tests_ += leaf.count;
    if (leaf_log_) test::note_leaf_test(leaf_log_, index_of(leaf), leaf.count, ray.tmax);
    return pt::leaf_occludes(scene_, leaves_, leaf.offset, leaf.count, ray);
  }
  uint32_t index_of(const BvhNode& node) const { return uint32_t(&node - nodes_.data()); }

  const Scene& scene_;
  std::vector<BvhNode> nodes_;
  LeafPrimitives leaves_;
  BvhStats stats_;
  uint64_t* primitive_tests_ = nullptr;
  test::LeafLog* leaf_log_ = nullptr;

  friend class BvhBuilder;
};

}  // namespace pt
