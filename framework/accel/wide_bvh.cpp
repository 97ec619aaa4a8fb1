#include "accel/wide_bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "1-raygen/scene_intersect.h"
#include "accel/sheared_triangle.h"

namespace pt {

WideBvh::WideBvh(const Scene& scene, const Bvh& binary) : scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<BvhNode>& bin = binary.nodes();
  order_ = binary.order();
  if (order_.size() != scene.primitive_count())
    throw std::invalid_argument("WideBvh: the binary tree holds " + std::to_string(order_.size()) +
                                " primitives but the scene has " +
                                std::to_string(scene.primitive_count()) +
                                " (was it built over another scene?)");
  corners_.resize(order_.size());
  is_triangle_.resize(order_.size());
  for (size_t i = 0; i < order_.size(); ++i) {
    const uint32_t prim = order_[i];
    is_triangle_[i] = scene.is_triangle(prim);
    if (!is_triangle_[i]) continue;
    const Triangle& t = scene.triangles[prim];
    corners_[i] = {scene.positions[t.v[0]], scene.positions[t.v[1]], scene.positions[t.v[2]]};
  }
  if (!bin.empty()) {
    nodes_.reserve(bin.size() / 2 + 1);
    packets_.reserve(bin.size() / 2 + 1);
    collapse(bin, 0, 0);
  }
  // The packets hold every corner: the exact test reads its lane from there.
  corners_.clear();
  corners_.shrink_to_fit();
  stats_.nodes = uint32_t(nodes_.size());
  size_t slots = 0;
  for (const WideNode& n : nodes_) {
    slots += n.children;
    for (int k = 0; k < n.children; ++k) stats_.leaves += n.count[k] > 0;
  }
  stats_.mean_children = nodes_.empty() ? 0.0 : double(slots) / double(nodes_.size());
  stats_.build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

uint32_t WideBvh::collapse(const std::vector<BvhNode>& bin, uint32_t index, uint32_t depth) {
  if (depth > uint32_t(Bvh::kMaxDepth))
    throw std::invalid_argument("WideBvh: the binary tree is deeper than Bvh::kMaxDepth (" +
                                std::to_string(Bvh::kMaxDepth) + ")");
  stats_.depth = std::max(stats_.depth, depth + 1);
  // A binary leaf at the root still gets a node above it, so every traversal starts the same way.
  uint32_t kids[4];
  int n = 0;
  if (bin[index].is_leaf()) {
    kids[n++] = index;
  } else {
    kids[n++] = index + 1;
    kids[n++] = bin[index].offset;
  }
  // Open the largest interior child until there are four: a big box is the one most rays enter.
  // Its two children take its place, in order, so slots stay in the binary tree's order (ties in
  // entry distance are visited as Part 2 visits them; see find_nearest).
  while (n < 4) {
    int open = -1;
    float area = -1.0f;
    for (int k = 0; k < n; ++k)
      if (!bin[kids[k]].is_leaf() && bin[kids[k]].bounds.surface_area() > area)
        open = k, area = bin[kids[k]].bounds.surface_area();
    if (open < 0) break;
    const uint32_t parent = kids[open];
    for (int k = n; k > open + 1; --k) kids[k] = kids[k - 1];
    kids[open] = parent + 1;
    kids[open + 1] = bin[parent].offset;
    ++n;
  }
  const uint32_t self = uint32_t(nodes_.size());
  nodes_.emplace_back();
  WideNode node;
  node.children = uint8_t(n);
  for (int k = 0; k < 4; ++k) {
    const Bounds3 b = k < n ? bin[kids[k]].bounds : Bounds3{};
    for (int a = 0; a < 3; ++a) {
      node.boxes.bounds[a][k] = b.lo[a];
      node.boxes.bounds[3 + a][k] = b.hi[a];
    }
    node.child[k] = 0;
    node.count[k] = 0;
  }
  for (int k = 0; k < n; ++k) {
    const BvhNode& c = bin[kids[k]];
    if (c.is_leaf()) {
      if (c.count > 255)
        throw std::invalid_argument("WideBvh: a leaf of " + std::to_string(c.count) +
                                    " primitives (at most 255)");
      node.child[k] = uint32_t(packets_.size());
      node.count[k] = uint8_t(c.count);
      // Lanes past the leaf's end and spheres' lanes hold NaN corners: never rejected by the
      // filter, they are sorted out by the caller (which knows the count) and the exact tests.
      for (uint32_t first = c.offset; first < c.offset + c.count; first += 4) {
        Triangle4 packet;
        for (int lane = 0; lane < 4; ++lane) {
          const uint32_t i = first + uint32_t(lane);
          const bool real = i < c.offset + c.count && is_triangle_[i];
          const glm::vec3* p = real ? &corners_[i].p0 : nullptr;
          for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a)
              packet.corner[v][a][lane] = real ? p[v][a] : std::nanf("");
        }
        packets_.push_back(packet);
        packet_entry_.push_back(first);
      }
      stats_.depth = std::max(stats_.depth, depth + 1);
    } else {
      node.child[k] = collapse(bin, kids[k], depth + 1);
    }
  }
  nodes_[self] = node;
  return self;
}

/// The best hit of a nearest-hit query so far, judged as brute force judges: the smallest
/// reported t, the lower primitive index on a tie.
struct WideBvh::Nearest {
  uint32_t prim = UINT32_MAX;
  float t = 0.0f;
  bool found() const { return prim != UINT32_MAX; }
  bool beaten_by(float t_new, uint32_t prim_new) const {
    return !found() || t_new < t || (t_new == t && prim_new < prim);
  }
};

namespace {

/// A node or leaf still to visit, with the distance at which the ray enters its box.
struct StackEntry {
  uint32_t child;
  uint32_t count;  ///< 0: `child` is a node; else a leaf of `count` entries from `child`
  float t;
};

}  // namespace

// kCheckEachCandidate: every triangle that would become the best is first made into a SurfaceHit
// (Part 2's way), for the rare ray whose winner Part 1 then refuses to shade (a triangle whose
// corners are collinear in float); otherwise only the winner is.
template <bool kCheckEachCandidate>
void WideBvh::find_nearest(const Ray& ray, Nearest* best) const {
  const ShearedRay sheared(ray);
  const ShearedRay4 sheared4(sheared);
  const Box4Ray box_ray(ray);
  // What boxes and triangles are culled by: the best t stretched by Part 2's kHitDistanceSlack, so
  // a rival an ulp nearer in another leaf is still compared; primitives are judged on their t.
  // A hit at a tiny t (a ray leaving a surface) can be off by far more than that relative slack:
  // the bound then also covers twice the winner's own error bound on t, since a rival reporting
  // the same t at the same spot (a duplicate, a coplanar neighbour) has an error of that size,
  // and its box, entered no later than its exact distance, must not be culled.
  float cull = ray.tmax;
  StackEntry stack[kStackSize];
  int top = 0;
  stack[top++] = {0, 0, ray.tmin};
  while (top > 0) {
    StackEntry e = stack[--top];
    if (e.t > cull) continue;
    for (;;) {
      if (e.count > 0) {
        const uint32_t first = packet_entry_[e.child], end = first + e.count;
        for (uint32_t p = e.child, base = first; base < end; ++p, base += 4) {
          unsigned lanes = triangle4_candidates(packets_[p], sheared4, cull);
          if (end - base < 4) lanes &= (1u << (end - base)) - 1u;
          for (; lanes; lanes &= lanes - 1) {
          const uint32_t i = base + uint32_t(__builtin_ctz(lanes));
          const uint32_t prim = order_[i];
          float t, t_error = 0.0f;
          if (is_triangle_[i]) {
            TriangleHit th;
            const Corners c = corners(p, i - base);
            if (!intersect_sheared_triangle(sheared, cull, c.p0, c.p1, c.p2, &th, &t_error))
              continue;
            if (!best->beaten_by(th.t, prim)) continue;
            t = th.t;
            if (kCheckEachCandidate) {
              SurfaceHit h;
              if (!intersect_primitive(scene_, prim, ray, &h)) continue;
            }
          } else {
            SurfaceHit h;
            if (!intersect_primitive(scene_, prim, ray, &h)) continue;
            if (!best->beaten_by(h.t, prim)) continue;
            t = h.t;
          }
          best->prim = prim;
          best->t = t;
          cull = std::min(ray.tmax,
                          t + std::max(std::abs(t) * (kHitDistanceSlack - 1.0f), 2.0f * t_error));
          }
        }
        break;
      }
      const WideNode& node = nodes_[e.child];
      alignas(16) float t_entry[4];
      unsigned mask = intersect_box4(node.boxes, box_ray, cull, t_entry);
      if (mask == 0) break;
      // Nearest child next; the others pushed farthest first, so they pop nearest first. Equal
      // entry distances go in slot order, as Part 2 goes into its first child on a tie: the
      // culling slack is relative, and a hit at a tiny t (a ray leaving a surface) can be off by
      // more than that, so of two coplanar rivals in different boxes the one visited first wins;
      // visiting them as Part 2 does keeps the answers the same as the binary tree's.
      StackEntry hits[4];
      int n = 0;
      while (mask) {
        const int k = __builtin_ctz(mask);
        mask &= mask - 1;
        StackEntry h{node.child[k], node.count[k], t_entry[k]};
        int j = n++;
        for (; j > 0 && hits[j - 1].t <= h.t; --j) hits[j] = hits[j - 1];
        hits[j] = h;
      }
      for (int k = 0; k < n - 1; ++k) stack[top++] = hits[k];
      e = hits[n - 1];
    }
  }
}

bool WideBvh::intersect(const Ray& ray, SurfaceHit* hit) const {
  if (nodes_.empty()) return false;
  Nearest best;
  find_nearest<false>(ray, &best);
  if (!best.found()) return false;
  // The winner's full hit, made the way brute force makes it (the same t, by construction).
  if (intersect_primitive(scene_, best.prim, ray, hit) && hit->t == best.t) return true;
  // Part 1 refused to shade the winner (corners collinear in float): look again, checking each
  // candidate, as Part 2 does.
  Nearest careful;
  find_nearest<true>(ray, &careful);
  return careful.found() && intersect_primitive(scene_, careful.prim, ray, hit);
}

bool WideBvh::occluded(const Ray& ray) const {
  if (nodes_.empty()) return false;
  const ShearedRay sheared(ray);
  const ShearedRay4 sheared4(sheared);
  const Box4Ray box_ray(ray);
  // Any occluder will do: no distances kept, no sorting.
  StackEntry stack[kStackSize];
  int top = 0;
  stack[top++] = {0, 0, 0.0f};
  while (top > 0) {
    const StackEntry e = stack[--top];
    if (e.count > 0) {
      const uint32_t first = packet_entry_[e.child], end = first + e.count;
      for (uint32_t p = e.child, base = first; base < end; ++p, base += 4) {
        unsigned lanes = triangle4_candidates(packets_[p], sheared4, ray.tmax);
        if (end - base < 4) lanes &= (1u << (end - base)) - 1u;
        for (; lanes; lanes &= lanes - 1) {
          const uint32_t i = base + uint32_t(__builtin_ctz(lanes));
          if (is_triangle_[i]) {
            TriangleHit th;
            const Corners c = corners(p, i - base);
            if (intersect_sheared_triangle(sheared, ray.tmax, c.p0, c.p1, c.p2, &th)) return true;
          } else if (primitive_occludes(scene_, order_[i], ray)) {
            return true;
          }
        }
      }
      continue;
    }
    const WideNode& node = nodes_[e.child];
    alignas(16) float t_entry[4];
    unsigned mask = intersect_box4(node.boxes, box_ray, ray.tmax, t_entry);
    while (mask) {
      const int k = __builtin_ctz(mask);
      mask &= mask - 1;
      stack[top++] = {node.child[k], node.count[k], 0.0f};
    }
  }
  return false;
}

}  // namespace pt
