// The app's wide BVH: the student's binary tree (Part 2) collapsed to eight children a node,
// traversed with four-box SIMD slab tests, answering exactly as brute force does.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "app/accel/box4.h"
#include "app/accel/ray_packet8.h"
#include "app/accel/triangle4.h"
#include "framework/geometry/ray_query.h"
#include "framework/scene/scene.h"
#include "parts/2-bvh/bvh.h"

namespace pt {

/// One node of the wide tree: its children's boxes side by side, four to a Box4, so that two
/// four-box SIMD slab tests answer for all eight. 256 bytes, four cache lines fetched together: the
/// traversal waits on memory, and eight children a node make fewer nodes in series on a ray's way
/// down than four.
struct alignas(64) WideNode {
  static constexpr int kWidth = 8;
  Box4 boxes[kWidth / 4];   ///< slot k in boxes[k / 4], lane k % 4; an unused slot holds an empty box
  uint32_t child[kWidth];   ///< interior child: its node index; leaf: its first packet
  uint8_t count[kWidth];    ///< leaf: how many primitives (1 .. 255); interior child or unused: 0
  /// Per octant of ray directions (o for sign bits o of x, y, z), the order to visit the slots in:
  /// three bits a position, first lowest, in three bytes; the binary splits' order for that
  /// direction. Every slot is named, those in use first, so a walk may go through all eight
  /// positions (an unused slot's empty box is never entered).
  uint8_t order[8][3] = {};

  /// The visiting order for octant `octant`, three bits a position.
  unsigned order_for(int octant) const {
    return unsigned(order[octant][0]) | unsigned(order[octant][1]) << 8 |
           unsigned(order[octant][2]) << 16;
  }
};

/// One packet of a wide leaf: up to four of its entries for the SIMD triangle test, with what each
/// lane holds, which primitive it is and its vertices, in four whole cache lines, so that visiting
/// a leaf reads nothing else (lane masks and primitive indices in arrays of their own cost a cache
/// miss each on a million-triangle mesh), and a full intersect can ask for the best triangle's
/// vertex data the moment it is found rather than after a miss on the scene's triangle record.
struct alignas(64) LeafPacket {
  Triangle4 tri;
  uint32_t prim[Triangle4::kLanes] = {};  ///< each lane's primitive (scene index)
  uint32_t first = 0;                     ///< leaf-order entry of lane 0
  uint32_t vertex[3][Triangle4::kLanes] = {};  ///< each triangle lane's vertex indices
  /// Bit k for lane k: an entry of the leaf (a triangle or a sphere); a triangle; an entry that
  /// may answer a nearest-hit query (a sphere, or a triangle Part 1 shades).
  uint8_t entries = 0, triangles = 0, nearest = 0;
};

static_assert(sizeof(WideNode) == 256 && sizeof(LeafPacket) == 256,
              "wide nodes and leaf packets are meant to fill whole cache lines");

/// What a collapse made, for bench and `pathtracer --info`.
struct WideBvhStats {
  uint32_t nodes = 0;
  uint32_t leaves = 0;
  uint32_t depth = 0;  ///< longest root-to-leaf path, in edges
  double mean_children = 0.0;
  double build_ms = 0.0;
};

/// What a nearest-hit query knows before any shading data is made, as Embree's rtcIntersect1
/// reports it: which primitive, how far, and where on it.
struct NearestHit {
  uint32_t primitive = 0;
  float t = 0.0f;
  /// A triangle's barycentric coordinates of the hit (b0 weighs its first corner); 0 for a sphere.
  float b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
};

/// A wide BVH over a scene's primitives (triangles and spheres), made from a binary Bvh by
/// pulling each node's largest grandchildren up until it has WideNode::kWidth children; a subtree of at most
/// kPackedLeafEntries entries, or neighbouring leaves that fit that together, become one leaf
/// (packets of the four-triangle SIMD test) where the surface area heuristic says one leaf is
/// cheaper than two, larger binary leaves are kept whole; a leaf whose entries lie far apart
/// (a room's walls) is opened into the groups the heuristic makes of them, largest box first,
/// as a subtree is opened into its halves; children are visited in an order
/// per octant of directions made from the binary splits. Answers the same queries as BruteForce
/// with the same answers: the nearest hit judged on the t each primitive reports (ties go to the
/// lower primitive index), its SurfaceHit made once, by Part 1's intersect_primitive, for the
/// winner only (or not at all: nearest()); and whether anything occludes a ray. The scene must
/// outlive it; the binary tree need not.
class WideBvh final : public RayQuery {
 public:
  WideBvh(const Scene& scene, const Bvh& binary);

  bool intersect(const Ray& ray, SurfaceHit* hit) const override;
  bool occluded(const Ray& ray) const override;
  /// The nearest hit's primitive, t and barycentrics, without its SurfaceHit: the very primitive
  /// and t intersect() reports, for callers (and benchmarks) that need no more.
  bool nearest(const Ray& ray, NearestHit* hit) const;
  /// occluded(rays[k]) as bit k of the answer, for the first bit k of `offered` (k < 8) and
  /// those other rays of `offered` that leave its origin (a shading point's shadow rays towards
  /// one light), which walk the tree together: a node's boxes culled for all of them by one test
  /// (RayPacket8), each ray then answered by its own box and leaf tests, so every bit is
  /// occluded()'s. *answered: the rays answered.
  unsigned occluded_together(const Ray* rays, unsigned offered, unsigned* answered) const;

  const WideBvhStats& stats() const { return stats_; }
  const std::vector<WideNode>& nodes() const { return nodes_; }
  /// How many slots of node `node` are in use (1 .. WideNode::kWidth).
  uint32_t children(uint32_t node) const { return children_[node]; }
  /// Primitive indices in leaf order (the binary tree's).
  const std::vector<uint32_t>& order() const { return order_; }
  /// The leaf-order entry of lane 0 of packet `packet` (a leaf's entries fill its packets in order).
  uint32_t packet_entry(uint32_t packet) const { return packets_[packet].first; }

  /// A subtree of at most this many entries may become one leaf (two packets), and neighbouring
  /// leaves may be merged up to it, where their union box is not much larger than the parts: the
  /// traversal waits on memory, and a node visit is a cache miss in series where a leaf's second
  /// packet arrives with its first.
  static constexpr uint32_t kPackedLeafEntries = 2 * Triangle4::kLanes;

  /// Entries a traversal stack can need: each visit pops one node and pushes at most all but
  /// one of its children.
  static constexpr int kStackSize = (WideNode::kWidth - 1) * Bvh::kMaxDepth + WideNode::kWidth;

 private:
  /// The corners of a triangle in leaf order (unused for a sphere's entry).
  struct Corners {
    glm::vec3 p0, p1, p2;
  };
  struct Nearest;

  uint32_t collapse(const std::vector<BvhNode>& binary, uint32_t index, uint32_t depth);
  /// Groups the leaf-order entries [first, first + count) (at most kPackedLeafEntries) as the
  /// surface area heuristic packs them; if that makes 2 to max_groups groups, reorders the
  /// entries so each group is a run, writes the runs' sizes to sizes[] and returns how many;
  /// else changes nothing and returns 1.
  int regroup_leaf(uint32_t first, uint32_t count, int max_groups, uint32_t* sizes);
  /// Appends the packets of the leaf-order entries [first, first + count).
  void add_packets(uint32_t first, uint32_t count);
  Corners corners(uint32_t packet, uint32_t lane) const {
    const Triangle4& t = packets_[packet].tri;
    return {{t.corner[0][0][lane], t.corner[0][1][lane], t.corner[0][2][lane]},
            {t.corner[1][0][lane], t.corner[1][1][lane], t.corner[1][2][lane]},
            {t.corner[2][0][lane], t.corner[2][1][lane], t.corner[2][2][lane]}};
  }
  template <bool kCheckEachCandidate, bool kPrefetchShading>
  void find_nearest(const Ray& ray, Nearest* best) const;
  /// occluded()'s walk below node `from` (the root, or where a packet's walk leaves a ray on its
  /// own), whose children `entered` the ray enters (not zero).
  bool occluded_below(const Ray& ray, const Box4Ray& box_ray, uint32_t from, unsigned entered) const;
#if PT_ACCEL_PACKETS
  /// occluded_rays' walk of the rays of `packet` (two or more lanes of `rays`).
  unsigned occluded_packet(const Ray* rays, const RayPacket8& packet) const;
#endif
  /// Whether an entry of the leaf of `count` entries from packet `first` blocks `ray`; the ray's
  /// shear is made in `storage` when first needed and kept in *sheared4.
  bool leaf_occludes(const Ray& ray, uint32_t first, uint32_t count, const ShearedRay4** sheared4,
                     unsigned char* storage) const;

  const Scene& scene_;
  std::vector<WideNode> nodes_;
  std::vector<uint8_t> children_;  ///< per node, its slots in use (not needed by a traversal)
  std::vector<uint32_t> order_;
  /// Each leaf's entries four at a time, for the SIMD triangle test.
  std::vector<LeafPacket> packets_;
  WideBvhStats stats_;
};

}  // namespace pt
