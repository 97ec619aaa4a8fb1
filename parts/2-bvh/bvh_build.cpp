// BVH construction: the plumbing around the student's split choices (binning, partitioning,
// flattening, statistics).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "2-bvh/bvh.h"

namespace pt {

namespace {

/// A primitive while the tree is built: its box, its box's centre and its index in the scene.
struct PrimRef {
  Bounds3 bounds;
  glm::vec3 centroid;
  uint32_t primitive;
};

bool finite_positive(float x) { return x > 0.0f && std::isfinite(x); }

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
      refs_[i] = {b, b.center(), i};
    }
    if (n == 0) return;
    bvh_.nodes_.reserve(2 * size_t(n / std::max(1, options_.max_leaf_size / 2)) + 1);
    build_node(0, n, 0);

    // The primitive order and the corner copies, in leaf order.
    bvh_.order_.resize(n);
    bvh_.corners_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t p = refs_[i].primitive;
      bvh_.order_[i] = p;
      if (scene.is_triangle(p)) {
        const Triangle& t = scene.triangles[p];
        bvh_.corners_[i] = {scene.positions[t.v[0]], scene.positions[t.v[1]],
                            scene.positions[t.v[2]]};
      }
    }
  }

 private:
  /// Builds the subtree over refs_[begin, end) at `depth`; returns its node index.
  uint32_t build_node(uint32_t begin, uint32_t end, uint32_t depth) {
    const uint32_t index = uint32_t(bvh_.nodes_.size());
    bvh_.nodes_.emplace_back();
    Bounds3 bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(refs_[i].bounds);
      centroids.grow(refs_[i].centroid);
    }
    bvh_.nodes_[index].bounds = bounds;
    BvhStats& st = bvh_.stats_;
    st.depth = std::max(st.depth, depth);

    const uint32_t n = end - begin;
    const uint32_t max_leaf = uint32_t(options_.max_leaf_size);
    uint32_t mid = n <= max_leaf ? begin : choose_and_partition(begin, end, bounds, centroids, depth);
    if (mid == begin || mid == end) {
      if (n <= max_leaf) return make_leaf(index, begin, n);
      // No plane separates them (equal centroids, or the student's split is still a stub): halve
      // by count, which always progresses.
      mid = begin + n / 2;
    }
    const uint32_t centroid_axis = uint32_t(centroids.longest_axis());
    build_node(begin, mid, depth + 1);
    const uint32_t second = build_node(mid, end, depth + 1);
    BvhNode& node = bvh_.nodes_[index];
    node.offset = second;
    node.axis = uint8_t(centroid_axis);
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

  /// Chooses a split and partitions refs_[begin, end) by it; returns the first index of the
  /// second side, or `begin` when a leaf is better (or no split separates anything).
  uint32_t choose_and_partition(uint32_t begin, uint32_t end, const Bounds3& bounds,
                                const Bounds3& centroids, uint32_t depth) {
    const glm::vec3 extent = centroids.extent();
    if (extent.x <= 0.0f && extent.y <= 0.0f && extent.z <= 0.0f) return begin;
    // Past this depth the heuristics have stopped making progress: split by count, which at most
    // doubles as often again as there are bits in a primitive index.
    if (depth >= uint32_t(Bvh::kMaxDepth - 34)) return median_partition(begin, end, centroids);

    const float area = bounds.surface_area();
    if (options_.split == BvhSplitMethod::sah && finite_positive(area)) {
      int best_axis = -1;
      SahSplit best;
      for (int axis = 0; axis < 3; ++axis) {
        // A denormal extent would make the bin scale infinite.
        if (!finite_positive(float(options_.sah_bins) / extent[axis])) continue;
        bin(begin, end, centroids, axis);
        const SahSplit s = best_sah_split(bins_, options_.sah_bins, area, options_.costs);
        if (s.plane >= 0 && s.cost < best.cost) best = s, best_axis = axis;
      }
      if (best_axis < 0) return begin;
      const BinMap map(centroids, best_axis, options_.sah_bins);
      return partition(begin, end, [&](const PrimRef& r) { return map(r.centroid) <= best.plane; });
    }
    const MidpointSplit s = midpoint_split(centroids);
    const int axis = std::clamp(s.axis, 0, 2);
    return partition(begin, end, [&](const PrimRef& r) { return r.centroid[axis] < s.position; });
  }

  /// Which bin a centroid falls into along one axis; the binning and the partition use this same
  /// map, so the counts the SAH weighed are the counts the partition makes.
  struct BinMap {
    BinMap(const Bounds3& centroids, int axis_, int bins_)
        : axis(axis_), lo(centroids.lo[axis_]), bins(bins_),
          scale(float(bins_) / (centroids.hi[axis_] - centroids.lo[axis_])) {}
    int operator()(const glm::vec3& c) const {
      const int k = int((c[axis] - lo) * scale);
      return std::clamp(k, 0, bins - 1);
    }
    int axis;
    float lo;
    int bins;
    float scale;
  };

  void bin(uint32_t begin, uint32_t end, const Bounds3& centroids, int axis) {
    const BinMap map(centroids, axis, options_.sah_bins);
    for (int k = 0; k < options_.sah_bins; ++k) bins_[k] = SahBin();
    for (uint32_t i = begin; i < end; ++i) {
      SahBin& b = bins_[map(refs_[i].centroid)];
      b.bounds.grow(refs_[i].bounds);
      ++b.count;
    }
  }

  template <class Pred>
  uint32_t partition(uint32_t begin, uint32_t end, Pred pred) {
    auto it = std::partition(refs_.begin() + begin, refs_.begin() + end, pred);
    return uint32_t(it - refs_.begin());
  }

  uint32_t median_partition(uint32_t begin, uint32_t end, const Bounds3& centroids) {
    const int axis = centroids.longest_axis();
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                     [axis](const PrimRef& a, const PrimRef& b) {
                       return a.centroid[axis] < b.centroid[axis];
                     });
    return mid;
  }

  Bvh& bvh_;
  BvhOptions options_;
  std::vector<PrimRef> refs_;
  SahBin bins_[kMaxSahBins];
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
