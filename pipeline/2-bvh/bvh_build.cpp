// Given code on Part 2: BVH construction, the plumbing around the student's split choices
// (binning, the leaf-or-split decision, partitioning, flattening, statistics).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "parts/2-bvh/bvh.h"

namespace pt {

namespace {

/// A primitive while the tree is built: its box, its index in the scene, and the binary exponent
/// of its box's surface area (the key of the size partitions). The centroid is recomputed from
/// the box rather than stored, to keep this at 32 bytes: the partitions move these around.
struct PrimRef {
  Bounds3 bounds;
  uint32_t primitive;
  int32_t size_exponent;
  glm::vec3 centroid() const { return bounds.center(); }
};

bool finite_positive(float x) { return x > 0.0f && std::isfinite(x); }

/// log2 of a box's surface area rounded down, exact and cheap (no log); a box of no area gets
/// the smallest exponent, so points and segments sort with the smallest primitives.
int32_t size_exponent(const Bounds3& b) {
  const float a = b.surface_area();
  return finite_positive(a) ? int32_t(std::ilogb(a)) : -150;
}

/// The families of partitions the SAH weighs: a plane across the centroids on each axis, and
/// (beyond the textbook's three) a cut between small and large primitives by box area. The
/// fourth is there for scenes where a few large triangles (a floor, walls) have centroids in
/// the middle of many small ones: no plane separates them, so plane-only splits drag the large
/// triangles' box down through level after level of the small ones' subtree.
constexpr int kFamilies = 4;
constexpr int kSizeFamily = 3;

}  // namespace

/// Builds a Bvh's arrays top-down; lives only for the duration of the constructor.
class BvhBuilder {
 public:
  BvhBuilder(Bvh* bvh, const BvhOptions& options) : bvh_(*bvh), options_(options) {}

  void build() {
    const Scene& scene = bvh_.scene_;
    const uint32_t n = scene.primitive_count();
    refs_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
      const Bounds3 b = scene.primitive_bounds(i);
      refs_[i] = {b, i, size_exponent(b)};
    }
    if (n == 0) return;
    // A binary tree over n primitives has at most 2n - 1 nodes: reserving that once spares the
    // copies of a growing vector (only the pages actually used are ever touched).
    bvh_.nodes_.reserve(2 * size_t(n) - 1);
    build_node(0, n, 0);

    // The primitive order, and with it the corner copies, in leaf order.
    std::vector<uint32_t> order(n);
    for (uint32_t i = 0; i < n; ++i) order[i] = refs_[i].primitive;
    bvh_.leaves_ = LeafPrimitives(scene, std::move(order));
  }

 private:
  /// Which bin a primitive falls into for one family of partitions; the binning and the
  /// partition use this same map, so the counts the SAH weighed are the counts the partition
  /// makes.
  struct BinMap {
    int family = 0;
    float lo = 0.0f;
    float scale = 0.0f;
    int bins = 1;
    int bin(float key) const { return std::clamp(int((key - lo) * scale), 0, bins - 1); }
    int operator()(const PrimRef& r) const {
      return bin(family == kSizeFamily ? float(r.size_exponent) : r.centroid()[family]);
    }
  };

  /// What to do with a node: keep it whole, or cut it between bin `plane` and the next of
  /// family `map`; axis is what the node records (the split axis).
  struct Choice {
    bool leaf = true;
    BinMap map;
    int plane = -1;
    int axis = 0;
  };

  /// Builds the subtree over refs_[begin, end) at `depth`; returns its node index.
  uint32_t build_node(uint32_t begin, uint32_t end, uint32_t depth) {
    const uint32_t index = uint32_t(bvh_.nodes_.size());
    bvh_.nodes_.emplace_back();
    Bounds3 bounds, centroids;
    int32_t size_lo = INT32_MAX, size_hi = INT32_MIN;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(refs_[i].bounds);
      centroids.grow(refs_[i].centroid());
      size_lo = std::min(size_lo, refs_[i].size_exponent);
      size_hi = std::max(size_hi, refs_[i].size_exponent);
    }
    bvh_.nodes_[index].bounds = bounds;
    BvhStats& st = bvh_.stats_;
    st.depth = std::max(st.depth, depth);

    const uint32_t n = end - begin;
    const uint32_t max_leaf = uint32_t(options_.max_leaf_size);
    if (n == 1) return make_leaf(index, begin, n);
    int axis = centroids.longest_axis();
    uint32_t mid = begin;
    if (depth >= uint32_t(Bvh::kMaxDepth - 34)) {
      // Past this depth the heuristics have stopped making progress: split by count, which at
      // most doubles as often again as there are bits in a primitive index.
      if (n <= max_leaf) return make_leaf(index, begin, n);
    } else if (options_.split == BvhSplitMethod::sah) {
      const Choice c = choose_sah(begin, end, bounds, centroids, size_lo, size_hi, n <= max_leaf);
      if (c.leaf && n <= max_leaf) return make_leaf(index, begin, n);
      if (!c.leaf) {
        axis = c.axis;
        mid = partition(begin, end, [&](const PrimRef& r) { return c.map(r) <= c.plane; });
      }
    } else {
      if (n <= max_leaf) return make_leaf(index, begin, n);
      const MidpointSplit s = midpoint_split(centroids);
      axis = std::clamp(s.axis, 0, 2);
      mid = partition(begin, end, [&](const PrimRef& r) { return r.centroid()[axis] < s.position; });
    }
    if (mid == begin || mid == end) {
      // No cut separates them (equal centroids, or the student's split is still a stub): halve
      // by count, which always progresses. Past the depth limit, halve at the median centroid;
      // otherwise in the order they are in, so duplicates stay in index order.
      axis = centroids.longest_axis();
      mid = depth >= uint32_t(Bvh::kMaxDepth - 34) ? median_partition(begin, end, axis)
                                                    : begin + n / 2;
    }
    build_node(begin, mid, depth + 1);
    const uint32_t second = build_node(mid, end, depth + 1);
    BvhNode& node = bvh_.nodes_[index];
    node.offset = second;
    node.axis = uint8_t(axis);
    return index;
  }

  uint32_t make_leaf(uint32_t index, uint32_t begin, uint32_t n) {
    BvhNode& node = bvh_.nodes_[index];
    node.offset = begin;
    node.count = uint16_t(n);
    ++bvh_.stats_.leaves;
    bvh_.stats_.max_leaf_size = std::max(bvh_.stats_.max_leaf_size, n);
    return index;
  }

  /// The cheapest cut of refs_[begin, end) by the SAH over every family, or a leaf when
  /// `leaf_allowed` and testing all n primitives costs no more than the cut (Wald 2007: the
  /// SAH's own termination rule, rather than splitting down to a fixed size).
  Choice choose_sah(uint32_t begin, uint32_t end, const Bounds3& bounds, const Bounds3& centroids,
                    int32_t size_lo, int32_t size_hi, bool leaf_allowed) {
    Choice best;
    const float area = bounds.surface_area();
    if (!finite_positive(area)) return best;
    const int bins = options_.sah_bins;

    // One map per family; a family whose keys are all equal cannot cut anything.
    BinMap maps[kFamilies];
    bool usable[kFamilies] = {};
    for (int f = 0; f < 3; ++f) {
      const float extent = centroids.hi[f] - centroids.lo[f];
      // A denormal extent would make the scale infinite.
      const float scale = float(bins) / extent;
      usable[f] = finite_positive(scale);
      maps[f] = {f, centroids.lo[f], usable[f] ? scale : 0.0f, bins};
    }
    // Size bins are whole binary exponents as long as there are bins enough for them.
    const int size_range = size_hi - size_lo + 1;
    usable[kSizeFamily] = size_range > 1;
    maps[kSizeFamily] = {kSizeFamily, float(size_lo),
                         size_range <= bins ? 1.0f : float(bins) / float(size_range), bins};

    if (end - begin == 2) {
      // Every family that can cut two primitives cuts them one from the other, at the same cost:
      // a third of all nodes are pairs, so they skip the bins.
      for (int f = 0; f < kFamilies; ++f) {
        if (!usable[f]) continue;
        const float cost = options_.costs.traversal +
                           options_.costs.intersection *
                               (refs_[begin].bounds.surface_area() +
                                refs_[begin + 1].bounds.surface_area()) / area;
        best.leaf = !(cost < 2.0f * options_.costs.intersection) && leaf_allowed;
        best.map = maps[f];
        best.plane = maps[f](refs_[begin]) < maps[f](refs_[begin + 1]) ? maps[f](refs_[begin])
                                                                       : maps[f](refs_[begin + 1]);
        best.axis = f == kSizeFamily ? centroids.longest_axis() : f;
        return best;
      }
      return best;
    }
    for (int f = 0; f < kFamilies; ++f)
      if (usable[f])
        for (int k = 0; k < bins; ++k) bins_[f][k] = SahBin();
    // Every family binned in one pass over the primitives.
    for (uint32_t i = begin; i < end; ++i) {
      const PrimRef& r = refs_[i];
      const glm::vec3 c = r.centroid();
      const float keys[kFamilies] = {c.x, c.y, c.z, float(r.size_exponent)};
      for (int f = 0; f < kFamilies; ++f) {
        if (!usable[f]) continue;
        SahBin& b = bins_[f][maps[f].bin(keys[f])];
        b.bounds.grow(r.bounds);
        ++b.count;
      }
    }

    float best_cost = std::numeric_limits<float>::infinity();
    for (int f = 0; f < kFamilies; ++f) {
      if (!usable[f]) continue;
      const SahSplit s = best_sah_split(bins_[f], bins, area, options_.costs);
      if (s.plane >= 0 && s.cost < best_cost) {
        best_cost = s.cost;
        best.leaf = false;
        best.map = maps[f];
        best.plane = s.plane;
        // A size cut has no axis; the node records the centroids' longest one.
        best.axis = f == kSizeFamily ? centroids.longest_axis() : f;
      }
    }
    const float leaf_cost = options_.costs.intersection * float(end - begin);
    if (leaf_allowed && !(best_cost < leaf_cost)) best.leaf = true;
    return best;
  }

  template <class Pred>
  uint32_t partition(uint32_t begin, uint32_t end, Pred pred) {
    auto it = std::partition(refs_.begin() + begin, refs_.begin() + end, pred);
    return uint32_t(it - refs_.begin());
  }

  uint32_t median_partition(uint32_t begin, uint32_t end, int axis) {
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                     [axis](const PrimRef& a, const PrimRef& b) {
                       return a.centroid()[axis] < b.centroid()[axis];
                     });
    return mid;
  }

  Bvh& bvh_;
  BvhOptions options_;
  std::vector<PrimRef> refs_;
  SahBin bins_[kFamilies][kMaxSahBins];
};

Bvh::Bvh(const Scene& scene, const BvhOptions& options) : scene_(scene) {
  if (options.max_leaf_size < 1 || options.max_leaf_size > kMaxLeafSize)
    throw std::invalid_argument("BVH leaf size must be between 1 and " +
                                std::to_string(kMaxLeafSize) + ", not " +
                                std::to_string(options.max_leaf_size));
  if (options.sah_bins < 2 || options.sah_bins > kMaxSahBins)
    throw std::invalid_argument("BVH SAH bins must be between 2 and " +
                                std::to_string(kMaxSahBins) + ", not " +
                                std::to_string(options.sah_bins));
  if (!finite_positive(options.costs.traversal) || !finite_positive(options.costs.intersection))
    throw std::invalid_argument("BVH SAH costs must be positive and finite");
  const auto start = std::chrono::steady_clock::now();
  BvhBuilder(this, options).build();
  const auto stop = std::chrono::steady_clock::now();

  stats_.build_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  stats_.primitives = scene.primitive_count();
  stats_.nodes = uint32_t(nodes_.size());
  stats_.split = options.split;
  if (stats_.leaves > 0) stats_.mean_leaf_size = double(stats_.primitives) / stats_.leaves;
  if (!nodes_.empty()) {
    const double root_area = nodes_[0].bounds.surface_area();
    double cost = 0.0;
    for (const BvhNode& node : nodes_) {
      const double w = root_area > 0.0 ? node.bounds.surface_area() / root_area : 1.0;
      cost += w * (node.is_leaf() ? options.costs.intersection * node.count
                                  : options.costs.traversal);
    }
    stats_.sah_cost = cost;
  }
}

}  // namespace pt
