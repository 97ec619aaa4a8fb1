// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#include "app/accel/wide_bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <glm/geometric.hpp>

#include "app/accel/ray_packet8.h"
#include "app/accel/sheared_triangle.h"
#include "app/accel/surface_hit_lanes.h"
#include "parts/1-raygen/sphere_intersect.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt {

namespace {

/// Asks the kernel to back a reserved but untouched array with huge pages where it can: the
/// arrays of a million-triangle tree span tens of megabytes, and faulting them in 4 KiB at a time
/// costs more than the collapse itself on a virtual machine. Only a hint: nothing changes if the
/// kernel says no.
template <class T>
void prefer_huge_pages(const std::vector<T>& v) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kHuge = uintptr_t(2) << 20;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(v.data()) + kHuge - 1) & ~(kHuge - 1);
  const uintptr_t end = reinterpret_cast<uintptr_t>(v.data() + v.capacity()) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)v;
#endif
}

}  // namespace

WideBvh::WideBvh(const Scene& scene, const Bvh& binary) : scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<BvhNode>& bin = binary.nodes();
  order_ = binary.order();
  if (order_.size() != scene.primitive_count())
    throw std::invalid_argument("WideBvh: the binary tree holds " + std::to_string(order_.size()) +
                                " primitives but the scene has " +
                                std::to_string(scene.primitive_count()) +
                                " (was it built over another scene?)");
  if (!bin.empty()) {
    // Upper bounds, so nothing is moved while the tree grows: every wide node but a lone root
    // leaf's consumes a binary interior node, and every packet holds at least one entry. The
    // capacity never touched costs address space, not memory.
    size_t interior = 0;
    for (const BvhNode& n : bin) interior += !n.is_leaf();
    nodes_.reserve(interior + 1);
    children_.reserve(interior + 1);
    packets_.reserve(order_.size());
    prefer_huge_pages(nodes_);
    prefer_huge_pages(packets_);
    collapse(bin, 0, 0);
  }
  stats_.nodes = uint32_t(nodes_.size());
  size_t slots = 0;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    slots += children_[i];
    for (int k = 0; k < children_[i]; ++k) stats_.leaves += nodes_[i].count[k] > 0;
  }
  stats_.mean_children = nodes_.empty() ? 0.0 : double(slots) / double(nodes_.size());
  stats_.build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

namespace {

/// Part 1's rule (intersect_primitive in scene_intersect.cpp), with its very operations: a
/// triangle whose corners are collinear in float (a normal of length 0, or one that overflows)
/// has no normal to shade or offset along, so a nearest-hit query never reports it.
bool part1_shades(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const float len = glm::length(glm::cross(p1 - p0, p2 - p0));
  return len > 0.0f && std::isfinite(len);
}

}  // namespace

void WideBvh::add_packets(uint32_t first, uint32_t count) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  // Lanes past the leaf's end and spheres' lanes hold NaN corners: never rejected by the
  // filter, they are left out by the packet's lane masks.
  for (uint32_t base = first; base < first + count; base += Triangle4::kLanes) {
    LeafPacket& lanes = packets_.emplace_back();
    Triangle4& packet = lanes.tri;
    lanes.first = base;
    for (uint32_t lane = 0; lane < Triangle4::kLanes; ++lane) {
      const uint32_t i = base + lane;
      const bool entry = i < first + count;
      const bool triangle = entry && scene_.is_triangle(order_[i]);
      lanes.entries |= uint8_t(entry) << lane;
      lanes.prim[lane] = entry ? order_[i] : 0;
      glm::vec3 p[3] = {glm::vec3(kNaN), glm::vec3(kNaN), glm::vec3(kNaN)};
      if (triangle) {
        const Triangle& t = scene_.triangles[order_[i]];
        for (int v = 0; v < 3; ++v) p[v] = scene_.positions[t.v[v]], lanes.vertex[v][lane] = t.v[v];
        lanes.triangles |= uint8_t(1u << lane);
        lanes.nearest |= uint8_t(part1_shades(p[0], p[1], p[2])) << lane;
      } else if (entry) {
        lanes.nearest |= uint8_t(1u << lane);  // a sphere: Part 1 is asked for each candidate
      }
      for (int v = 0; v < 3; ++v)
        for (int a = 0; a < 3; ++a) packet.corner[v][a][lane] = p[v][a];
    }
  }
}

namespace {

/// One child slot of a wide node while it is being made: a binary subtree still to collapse, or
/// a run of leaf-order entries that becomes one wide leaf.
struct Slot {
  uint32_t node;   ///< the binary node (for a run merged from several subtrees: the first one's)
  uint32_t first;  ///< leaf: first leaf-order entry
  uint32_t count;  ///< leaf: entries; 0 for a subtree still to collapse
  Bounds3 box;
  float area;
  uint32_t small = 0;  ///< a subtree of at most WideBvh::kPackedLeafEntries: its entries
  /// A leaf to keep as it is: regrouping it was tried (or it is a group, or a merge, already).
  bool whole = false;
  /// The way down from the wide node's own binary node: at step d the split axis[d], and bit d of
  /// `right` set where it went into the second child. A merged run keeps the common part.
  static constexpr int kMaxPath = 16;
  uint8_t depth = 0;
  uint8_t axis[kMaxPath] = {};
  uint32_t right = 0;

  /// This slot's child `side` (0 first, 1 second) of binary node `parent`, one step further down.
  void descend(const Slot& from, const BvhNode& parent, int side) {
    depth = from.depth, right = from.right;
    std::copy(from.axis, from.axis + kMaxPath, axis);
    if (depth < kMaxPath) {  // deeper than that only the order is approximate
      axis[depth] = parent.axis;
      right |= uint32_t(side) << depth;
      ++depth;
    }
  }
  /// Keeps only the way down that this slot and `next`, its neighbour, share.
  void share_path(const Slot& next) {
    int d = 0;
    while (d < depth && d < next.depth && (right >> d & 1u) == (next.right >> d & 1u)) ++d;
    depth = uint8_t(d);
    right &= (1u << d) - 1u;
  }
};

/// Whether, for rays whose direction has the signs of `octant` (bit a: negative along axis a),
/// slot b (after slot a in slot order) should be visited before slot a: where their ways down
/// part, the binary tree split along some axis with a's side below b's, so a ray going down that
/// axis meets b's side first. Where one way is part of the other, slot order stays.
bool visit_before(const Slot& b, const Slot& a, unsigned octant) {
  const int shared = std::min(a.depth, b.depth);
  const uint32_t differ = (a.right ^ b.right) & ((uint64_t(1) << shared) - 1u);
  return differ != 0 && (octant >> a.axis[__builtin_ctz(differ)] & 1u) != 0;
}

/// Per octant of ray directions, the order to visit the n slots in (see WideNode::order): the n
/// slots in use first, then the unused ones.
void octant_orders(const Slot* slots, int n, uint8_t orders[8][3]) {
  for (unsigned octant = 0; octant < 8; ++octant) {
    int order[WideNode::kWidth];
    for (int j = 0; j < WideNode::kWidth; ++j) order[j] = j;
    for (int i = 1; i < n; ++i)  // stable insertion sort: ties keep slot order
      for (int j = i; j > 0 && visit_before(slots[order[j]], slots[order[j - 1]], octant); --j)
        std::swap(order[j], order[j - 1]);
    uint32_t bits = 0;
    for (int j = 0; j < WideNode::kWidth; ++j) bits |= uint32_t(order[j]) << (3 * j);
    for (int b = 0; b < 3; ++b) orders[octant][b] = uint8_t(bits >> (8 * b));
  }
}

/// How many entries the binary subtree at `index` holds, if at most `limit`; else limit + 1.
/// Stops as soon as it knows, so asking costs at most a few nodes however large the subtree.
uint32_t entries_up_to(const std::vector<BvhNode>& bin, uint32_t index, uint32_t limit,
                       uint32_t* first) {
  const BvhNode& n = bin[index];
  if (n.is_leaf()) {
    *first = n.offset;
    return n.count;
  }
  const uint32_t left = entries_up_to(bin, index + 1, limit, first);
  if (left > limit) return limit + 1;
  uint32_t unused;
  return std::min(left + entries_up_to(bin, n.offset, limit - left, &unused), limit + 1);
}

/// A wide node's visit, in the units of leaf_cost: its eight-box test and its four cache lines,
/// about two packet tests (on CBbunny, 1 or 2 here give trees within a percent of each other in
/// a render's instruction count; 1 makes half again as many nodes).
constexpr float kNodeVisitCost = 2.0f;

/// What a ray that enters a leaf of n entries costs, in SIMD packet tests: the visit itself and a
/// test per four entries. Only ratios of these are used.
float leaf_cost(uint32_t n) {
  return 1.0f + float((n + Triangle4::kLanes - 1) / Triangle4::kLanes);
}

/// Whether entries in boxes a (na of them) and b (nb) are cheaper as one leaf than apart, by the
/// surface area heuristic (a ray enters a box about in proportion to its area), where keeping
/// them apart costs `apart_extra` per unit of their union's area besides their own leaves (a
/// wide node of their own, when they cannot be two slots of the node being made). Neighbouring
/// triangles of a mesh, whose union box is hardly larger than each, are packed (their packets'
/// lanes are full, and one leaf is one cache miss); a Cornell box's walls, whose union is the
/// whole room, are not, so a shadow ray tests the one or two walls it comes near instead of all.
bool packing_pays(const Bounds3& a, uint32_t na, const Bounds3& b, uint32_t nb,
                  float apart_extra = 0.0f) {
  Bounds3 both = a;
  both.grow(b);
  const float area = both.surface_area();
  return area * leaf_cost(na + nb) <=
         area * apart_extra + a.surface_area() * leaf_cost(na) + b.surface_area() * leaf_cost(nb);
}

/// Whether the small subtree of slot `s` (s.small entries, a binary interior node) pays as one
/// leaf, if it is a slot of its own (apart_extra 0) or would otherwise become a wide node of its
/// own (apart_extra: kNodeVisitCost).
bool pack_subtree(const std::vector<BvhNode>& bin, const Slot& s, float apart_extra) {
  const BvhNode& node = bin[s.node];
  uint32_t unused;
  const uint32_t left = entries_up_to(bin, s.node + 1, s.small, &unused);
  return packing_pays(bin[s.node + 1].bounds, left, bin[node.offset].bounds, s.small - left,
                      apart_extra);
}

/// The slot for binary node `index`: a leaf when it is a binary leaf or its whole subtree fits
/// WideBvh::kPackedLeafEntries and packing its two halves pays (the binary tree's small leaves
/// are packed four triangles to a packet, so the SIMD test's lanes are full), else a subtree to
/// open or collapse.
Slot make_slot(const std::vector<BvhNode>& bin, uint32_t index) {
  const BvhNode& node = bin[index];
  Slot s{index, 0, 0, node.bounds, node.bounds.surface_area()};
  const uint32_t n = entries_up_to(bin, index, WideBvh::kPackedLeafEntries, &s.first);
  if (node.is_leaf()) {
    s.count = n;
  } else if (n <= WideBvh::kPackedLeafEntries) {
    s.small = n;
    if (pack_subtree(bin, s, 0.0f)) s.count = n;
  }
  return s;
}

}  // namespace

int WideBvh::regroup_leaf(uint32_t first, uint32_t count, int max_groups, uint32_t* sizes) {
  // The arrays below hold a packed leaf: a longer run is left as it is.
  if (count < 2 || count > kPackedLeafEntries) return 1;
  // Start from one group an entry and join the pair that pays most, while a pair pays.
  struct Group {
    Bounds3 box;
    uint32_t count;
  };
  Group groups[kPackedLeafEntries];
  uint32_t member[kPackedLeafEntries];  ///< each entry's group
  int n = int(count);
  for (uint32_t e = 0; e < count; ++e) {
    groups[e] = {scene_.primitive_bounds(order_[first + e]), 1};
    member[e] = e;
  }
  for (;;) {
    int best_i = -1, best_j = -1;
    float best_gain = 0.0f;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const Group &a = groups[i], &b = groups[j];
        if (!packing_pays(a.box, a.count, b.box, b.count)) continue;
        Bounds3 both = a.box;
        both.grow(b.box);
        const float gain = a.box.surface_area() * leaf_cost(a.count) +
                           b.box.surface_area() * leaf_cost(b.count) -
                           both.surface_area() * leaf_cost(a.count + b.count);
        if (best_i < 0 || gain > best_gain) best_i = i, best_j = j, best_gain = gain;
      }
    if (best_i < 0) break;
    groups[best_i].box.grow(groups[best_j].box);
    groups[best_i].count += groups[best_j].count;
    for (uint32_t e = 0; e < count; ++e) {
      if (member[e] == uint32_t(best_j)) member[e] = uint32_t(best_i);
      if (member[e] == uint32_t(n - 1)) member[e] = uint32_t(best_j);
    }
    groups[best_j] = groups[n - 1];
    --n;
  }
  if (n < 2 || n > max_groups) return 1;
  // The groups in the order of their first entries (met walking the leaf), each group's entries
  // in the leaf's order.
  bool placed[kPackedLeafEntries] = {};
  uint32_t reordered[kPackedLeafEntries];
  uint32_t out = 0;
  int r = 0;
  for (uint32_t e = 0; e < count; ++e) {
    const uint32_t g = member[e];
    if (placed[g]) continue;
    placed[g] = true;
    for (uint32_t k = e; k < count; ++k)
      if (member[k] == g) reordered[out++] = order_[first + k];
    sizes[r++] = groups[g].count;
  }
  std::copy(reordered, reordered + count, order_.begin() + first);
  return n;
}

uint32_t WideBvh::collapse(const std::vector<BvhNode>& bin, uint32_t index, uint32_t depth) {
  if (depth > uint32_t(Bvh::kMaxDepth))
    throw std::invalid_argument("WideBvh: the binary tree is deeper than Bvh::kMaxDepth (" +
                                std::to_string(Bvh::kMaxDepth) + ")");
  stats_.depth = std::max(stats_.depth, depth + 1);
  // A leaf at the root still gets a node above it, so every traversal starts the same way.
  constexpr int kWidth = WideNode::kWidth;
  Slot slots[kWidth];
  uint32_t group_sizes[WideBvh::kPackedLeafEntries];
  int n = 0;
  slots[n++] = make_slot(bin, index);
  // Leaf slot k's entries grouped again as the area heuristic would pack them, where that makes
  // 2 or more groups that fit the slots left: each group takes a slot. Returns the groups made
  // (1: nothing changed).
  auto split_leaf = [&](int k) {
    const Slot leaf = slots[k];
    const int groups = regroup_leaf(leaf.first, leaf.count, kWidth - n + 1, group_sizes);
    if (groups < 2) return 1;
    const int extra = groups - 1;
    for (int j = n - 1; j > k; --j) slots[j + extra] = slots[j];
    uint32_t first = leaf.first;
    for (int g = 0; g < groups; ++g) {
      Slot& part = slots[k + g];
      part = leaf;
      part.first = first;
      part.count = group_sizes[g];
      part.whole = true;
      part.box = Bounds3{};
      for (uint32_t e = first; e < first + part.count; ++e)
        part.box.grow(scene_.primitive_bounds(order_[e]));
      part.area = part.box.surface_area();
      first += part.count;
    }
    n += extra;
    return groups;
  };
  // Slots stay in the binary tree's order throughout, so neighbouring leaves hold neighbouring
  // entries, and each slot remembers its way down, from which the visiting orders are made.
  for (;;) {
    // Open the largest box until every slot is used: a big box is the one most rays enter. A
    // subtree opens into its two halves; a packed leaf whose entries lie far apart opens into
    // the groups the area heuristic makes of them. A Cornell box's walls are such a leaf: the
    // binary tree pairs them, each pair as large as the room, so one leaf of all eight triangles
    // looked cheaper than two halves, yet every ray in the room entered it and tested them all,
    // while a wall alone is a thin slab that only the rays that meet it enter (CBbunny's leaf of
    // walls was tested by every shadow ray; its walls now take four slots of the root).
    while (n < kWidth) {
      int open = -1;
      for (int k = 0; k < n; ++k) {
        const bool can_open = slots[k].count == 0 || (slots[k].count >= 2 && !slots[k].whole);
        if (can_open && (open < 0 || slots[k].area > slots[open].area)) open = k;
      }
      if (open < 0) break;
      if (slots[open].count > 0) {
        if (split_leaf(open) < 2) slots[open].whole = true;
        continue;
      }
      const BvhNode& parent = bin[slots[open].node];
      const Slot from = slots[open];
      for (int k = n; k > open + 1; --k) slots[k] = slots[k - 1];
      slots[open + 1] = make_slot(bin, parent.offset);
      slots[open + 1].descend(from, parent, 1);
      slots[open] = make_slot(bin, from.node + 1);
      slots[open].descend(from, parent, 0);
      ++n;
    }
    // Neighbouring leaves that fit one packed leaf together become one: a half-empty packet
    // costs a whole SIMD test, and the slot freed may open a subtree instead.
    bool merged = false;
    for (int k = 0; k + 1 < n; ++k) {
      Slot& a = slots[k];
      const Slot& b = slots[k + 1];
      if (a.count == 0 || b.count == 0 || a.count + b.count > WideBvh::kPackedLeafEntries ||
          !packing_pays(a.box, a.count, b.box, b.count))
        continue;
      a.count += b.count;
      a.whole = true;  // packing them pays: no regrouping apart
      a.box.grow(b.box);
      a.area = a.box.surface_area();
      a.share_path(b);
      for (int j = k + 1; j + 1 < n; ++j) slots[j] = slots[j + 1];
      --n;
      --k;  // the grown leaf may take its next neighbour too
      merged = true;
    }
    if (!merged || n == kWidth) break;
    bool can_open = false;
    for (int k = 0; k < n; ++k) can_open |= slots[k].count == 0;
    if (!can_open) break;
  }
  // A small subtree left closed would become a wide node of its own: a leaf may pay now.
  for (int k = 0; k < n; ++k)
    if (slots[k].count == 0 && slots[k].small > 0 && pack_subtree(bin, slots[k], kNodeVisitCost))
      slots[k].count = slots[k].small;
  // Slots still free (a scene of a few primitives): a leaf of the student's tree may hold entries
  // far apart (CBspheres_lambertian's floor and both spheres, in one box from the floor to the
  // spheres' tops, which every shadow ray from the floor starts in), so its entries are grouped
  // again as the area heuristic would pack them (a quad's two triangles stay together, the
  // spheres go apart), and the groups take a slot each where there is room.
  for (int k = 0; k < n; ++k) {
    if (n == kWidth) break;  // no slot left (regroup_leaf passes over a run it cannot regroup)
    k += split_leaf(k) - 1;
  }
  const uint32_t self = uint32_t(nodes_.size());
  {
    WideNode& node = nodes_.emplace_back();
    children_.push_back(uint8_t(n));
    octant_orders(slots, n, node.order);
    for (int k = 0; k < kWidth; ++k) {
      const Bounds3 b = k < n ? slots[k].box : Bounds3{};
      for (int a = 0; a < 3; ++a) {
        node.boxes[k / 4].bounds[a][k % 4] = b.lo[a];
        node.boxes[k / 4].bounds[3 + a][k % 4] = b.hi[a];
      }
      node.child[k] = 0;
      node.count[k] = 0;
    }
  }
  // Written through the index: collapsing a child appends to nodes_.
  for (int k = 0; k < n; ++k) {
    const Slot& c = slots[k];
    if (c.count > 0) {
      if (c.count > 255)
        throw std::invalid_argument("WideBvh: a leaf of " + std::to_string(c.count) +
                                    " primitives (at most 255)");
      nodes_[self].child[k] = uint32_t(packets_.size());
      nodes_[self].count[k] = uint8_t(c.count);
      add_packets(c.first, c.count);
    } else {
      const uint32_t child = collapse(bin, c.node, depth + 1);
      nodes_[self].child[k] = child;
    }
  }
  return self;
}

/// The best hit of a nearest-hit query so far, judged as brute force judges: the smallest
/// reported t, the lower primitive index on a tie.
struct WideBvh::Nearest {
  uint32_t prim = UINT32_MAX;
  float t = 0.0f;
  float b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
  uint32_t packet = 0, lane = 0;  ///< where the best triangle's corners and vertices are
  bool found() const { return prim != UINT32_MAX; }
  bool beaten_by(float t_new, uint32_t prim_new) const {
    return !found() || t_new < t || (t_new == t && prim_new < prim);
  }
};

namespace {

/// Asks for the cache lines of a child the ray enters as soon as its box test says so, so that
/// the misses of all the children entered overlap (and a pushed child's lines arrive while its
/// siblings are visited) instead of each stalling the traversal in turn when it is reached.
inline void prefetch_lines(const void* p, int lines) {
  const char* c = static_cast<const char*>(p);
  for (int i = 0; i < lines; ++i) __builtin_prefetch(c + 64 * i);
}

/// Which of a node's children the ray enters (bit k for slot k), and where (t_entry[k]).
inline unsigned intersect_node(const WideNode& node, const Box4Ray& ray, float tmax,
                               float t_entry[WideNode::kWidth]) {
  static_assert(WideNode::kWidth == 8, "a node is two Box4");
  return intersect_box8(node.boxes, ray, tmax, t_entry);
}

/// The cache lines of a leaf of `count` entries; a large binary leaf's first two packets only.
inline int leaf_lines(uint32_t count) {
  return count > Triangle4::kLanes ? int(2 * sizeof(LeafPacket) / 64) : int(sizeof(LeafPacket) / 64);
}

/// A traversal that would push past WideBvh::kStackSize entries. For a traceable ray the bound
/// holds by construction (each level down pushes at most all but one of a node's children, and
/// the tree is no deeper than Bvh::kMaxDepth); a push is still checked, so a broken invariant is
/// an exception, never a write past the stack.
[[noreturn]] void stack_overflow() {
  throw std::logic_error("WideBvh: the traversal stack would overflow (a tree deeper than "
                         "Bvh::kMaxDepth, or a box test that lets a ray into every child)");
}

/// Whether a leaf's packets are tested two at a time: eight lanes a test where the build has AVX;
/// without it, one packet a test is the same work without the copying.
constexpr bool kPairPackets = PT_ACCEL_AVX != 0;

/// Bit j set for each position j of a visiting order (three bits a position, as
/// WideNode::order_for gives it) that names a slot set in `mask`.
inline unsigned entered_positions(unsigned mask, unsigned order) {
#ifdef __AVX2__
  // Lane j shifts the mask left until its slot's bit is the sign bit, which a movemask collects:
  // eight variable shifts in one instruction, where the scalar form took eight shift-and-mask
  // chains on every node visit of a nearest-hit walk (a tenth of its instructions).
  const __m256i shifts = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  const __m256i slot = _mm256_and_si256(_mm256_srlv_epi32(_mm256_set1_epi32(int(order)), shifts),
                                        _mm256_set1_epi32(7));
  const __m256i up = _mm256_sllv_epi32(_mm256_set1_epi32(int(mask)),
                                       _mm256_sub_epi32(_mm256_set1_epi32(31), slot));
  return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(up)));
#else
  unsigned positions = 0;
  for (int j = 0; j < WideNode::kWidth; ++j)
    positions |= (mask >> ((order >> (3 * j)) & 7u) & 1u) << j;
  return positions;
#endif
}

/// A node or leaf still to visit, with the distance at which the ray enters its box.
struct StackEntry {
  uint32_t child;
  uint32_t count;  ///< 0: `child` is a node; else a leaf of `count` entries from `child`
  float t;
};

}  // namespace

// kCheckEachCandidate: every triangle that would become the best is first made into a SurfaceHit
// (Part 2's way), for the rare ray whose winner Part 1 then refuses to shade (a triangle whose
// corners are collinear in float); otherwise only the winner is. kPrefetchShading: the caller will
// make the winner's SurfaceHit, so each new best triangle's record (its material) and normals are
// asked for at once, from the vertex indices its packet holds (waiting on the record first was
// most of the cost of a full intersect over a nearest query); its corners are in the packet.
template <bool kCheckEachCandidate, bool kPrefetchShading>
void WideBvh::find_nearest(const Ray& ray, Nearest* best) const {
  const ShearedRay4 sheared4(ray);
  const ShearedRay& sheared = sheared4.r;
  const Box4Ray box_ray(ray);
  // What boxes and triangles are culled by: the best t stretched by kHitDistanceSlack, so
  // a rival an ulp nearer in another leaf is still compared; primitives are judged on their t.
  // A hit at a tiny t (a ray leaving a surface) can be off by far more than that relative slack:
  // the bound then also covers twice the winner's own error bound on t, since a rival reporting
  // the same t at the same spot (a duplicate, a coplanar neighbour) has an error of that size,
  // and its box, entered no later than its exact distance, must not be culled.
  float cull = ray.tmax;
  const int octant = box_ray.octant;
  StackEntry stack[kStackSize];
  int top = 0;
  stack[top++] = {0, 0, ray.tmin};
  while (top > 0) {
    StackEntry e = stack[--top];
    if (e.t > cull) continue;
    for (;;) {
      if (e.count > 0) {
        // The lanes a test of packets [p, p + n) reported, lane k in packet p + k / 4, in order;
        // each hit checked again against the cull as it is now (an earlier lane's hit may have
        // brought it nearer since the test).
        auto take = [&](const auto& h, uint32_t first_packet) {
          for (unsigned lanes = h.hit | h.retest; lanes; lanes &= lanes - 1) {
            const uint32_t k = uint32_t(__builtin_ctz(lanes));
            const uint32_t p = first_packet + k / Triangle4::kLanes;
            const uint32_t lane = k % Triangle4::kLanes;
            const LeafPacket& info = packets_[p];
            const uint32_t prim = info.prim[lane];
            float t_error = 0.0f;
            TriangleHit th;
            if (info.triangles >> lane & 1u) {
              if (h.hit >> k & 1u) {
                if (!h.still_hits(k, cull)) continue;
                th = {h.t[k], h.b0[k], h.b1[k], h.b2[k]};
                t_error = h.t_error[k];
              } else {
                const Corners c = corners(p, lane);
                if (!intersect_sheared_triangle(sheared, cull, c.p0, c.p1, c.p2, &th, &t_error))
                  continue;
              }
              if (!best->beaten_by(th.t, prim)) continue;
              if (kCheckEachCandidate) {
                SurfaceHit sh;
                if (!intersect_primitive(scene_, prim, ray, &sh)) continue;
              }
            } else {
              // A sphere: judged on the t of Part 1's test, and made into a SurfaceHit only if it
              // wins (as a triangle is), unless each candidate must be checked.
              float t_sphere;
              if (kCheckEachCandidate) {
                SurfaceHit sh;
                if (!intersect_primitive(scene_, prim, ray, &sh)) continue;
                t_sphere = sh.t;
              } else if (!intersect_sphere(ray, scene_.spheres[prim - scene_.triangles.size()],
                                           &t_sphere)) {
                continue;
              }
              if (!best->beaten_by(t_sphere, prim)) continue;
              th.t = t_sphere;
            }
            if (kPrefetchShading && prim < scene_.triangles.size()) {
              // The corners are in this packet; the record (for the material) and the normals
              // are all the SurfaceHit reads elsewhere.
              __builtin_prefetch(&scene_.triangles[prim]);
              if (!scene_.normals.empty())
                for (int v = 0; v < 3; ++v) __builtin_prefetch(&scene_.normals[info.vertex[v][lane]]);
            }
            best->prim = prim;
            best->packet = p, best->lane = lane;
            best->t = th.t;
            best->b0 = th.b0, best->b1 = th.b1, best->b2 = th.b2;
            cull = std::min(ray.tmax, th.t + std::max(std::abs(th.t) * (kHitDistanceSlack - 1.0f),
                                                      2.0f * t_error));
          }
        };
        const uint32_t end = e.child + (e.count + Triangle4::kLanes - 1) / Triangle4::kLanes;
        for (uint32_t p = e.child; p < end;) {
          if (packets_[p].triangles == 0) {
            // Spheres only: every lane would come back from the lane test as a retest (its
            // corners are NaN), so each goes straight to Part 1's sphere test, in the same order.
            const LeafPacket& a = packets_[p];
            Triangle4Hits h;
            h.hit = 0;
            h.retest = kCheckEachCandidate ? a.entries : a.nearest;
            take(h, p);
            p += 1;
            continue;
          }
          if (kPairPackets && p + 1 < end) {
            const LeafPacket &a = packets_[p], &b = packets_[p + 1];
            const unsigned lanes = kCheckEachCandidate ? (a.entries | unsigned(b.entries) << 4)
                                                       : (a.nearest | unsigned(b.nearest) << 4);
            Triangle8Hits h;
            triangle8_intersect(a.tri, b.tri, sheared4, cull, lanes, &h);
            take(h, p);
            p += 2;
          } else {
            const LeafPacket& a = packets_[p];
            Triangle4Hits h;
            triangle4_intersect(a.tri, sheared4, cull, kCheckEachCandidate ? a.entries : a.nearest,
                                &h);
            take(h, p);
            p += 1;
          }
        }
        break;
      }
      const WideNode& node = nodes_[e.child];
      alignas(32) float t_entry[WideNode::kWidth];
      const unsigned mask = intersect_node(node, box_ray, cull, t_entry);
      if (mask == 0) break;
      // Children in the node's order for the ray's octant (front to back across each binary
      // split, which needs no sorting of entry distances): the first visited at once, the others
      // pushed last first, so they pop in that order; each is still culled by its entry distance
      // when popped. Which of two coplanar rivals in different boxes is seen first can matter (a
      // hit at a tiny t can be off by more than the relative slack), and this order is the one a
      // front-to-back walk of the binary tree takes; the accel tests and bench check that the
      // answers stay brute force's and the binary tree's.
      const unsigned order = node.order_for(octant);
      // Which positions of the order hold an entered child, found without a branch, so the walk
      // below goes through those only (a node's children are entered one or two at a time, and a
      // test per position was a branch the predictor could not learn).
      unsigned positions = entered_positions(mask, order);
      int next = -1;
      while (positions) {
        const int j = 31 - __builtin_clz(positions);
        positions &= ~(1u << j);
        const int k = int(order >> (3 * j)) & 7;
        if (node.count[k] > 0)
          prefetch_lines(&packets_[node.child[k]], leaf_lines(node.count[k]));
        else
          prefetch_lines(&nodes_[node.child[k]], int(sizeof(WideNode) / 64));
        if (next >= 0) {
          if (top == kStackSize) stack_overflow();
          stack[top++] = {node.child[next], node.count[next], t_entry[next]};
        }
        next = k;
      }
      e = {node.child[next], node.count[next], t_entry[next]};
    }
  }
}

bool WideBvh::intersect(const Ray& ray, SurfaceHit* hit) const {
  if (nodes_.empty() || !traceable(ray)) return false;
  Nearest best;
  find_nearest<false, true>(ray, &best);
  if (!best.found()) return false;
  // The winner's full hit, made as brute force makes it: a triangle's from the t and barycentrics
  // its test reported (bit-identical to Part 1's, so no second test), a sphere's by Part 1.
  if (scene_.is_triangle(best.prim)) {
    // From the corners and vertex indices of the packet the test just read (the scene's own
    // values, copied), so nothing waits on the triangle's record to find them.
    const LeafPacket& packet = packets_[best.packet];
    const Corners c = corners(best.packet, best.lane);
    const uint32_t vertex[3] = {packet.vertex[0][best.lane], packet.vertex[1][best.lane],
                                packet.vertex[2][best.lane]};
    if (triangle_surface_hit_in_lanes(scene_, best.prim, TriangleHit{best.t, best.b0, best.b1, best.b2},
                                      c.p0, c.p1, c.p2, vertex, hit))
      return true;
  } else if (intersect_primitive(scene_, best.prim, ray, hit) && hit->t == best.t) {
    return true;
  }
  // Part 1 refused to shade the winner (corners collinear in float): look again, checking each
  // candidate, as Part 2 does.
  Nearest careful;
  find_nearest<true, false>(ray, &careful);
  return careful.found() && intersect_primitive(scene_, careful.prim, ray, hit);
}

bool WideBvh::nearest(const Ray& ray, NearestHit* hit) const {
  if (nodes_.empty() || !traceable(ray)) return false;
  Nearest best;
  find_nearest<false, false>(ray, &best);
  if (!best.found()) return false;
  *hit = {best.prim, best.t, best.b0, best.b1, best.b2};
  return true;
}

// Whether an entry of the leaf of `count` entries from packet `first` blocks `ray`: the leaf
// test of every any-hit walk, single ray or packet, so both answer each ray alike. The shear is
// made in `storage` at the first packet of triangles and kept in *sheared4 for the ray's next
// leaves.
[[gnu::always_inline]] inline bool WideBvh::leaf_occludes(const Ray& ray, uint32_t first,
                                                          uint32_t count,
                                                          const ShearedRay4** sheared4,
                                                          unsigned char* storage) const {
  // Whether a lane a test of packets from `first_packet` handed back (or a sphere's lane)
  // occludes the ray. A triangle's lane is only handed back by a lane test, which made the
  // shear.
  auto retest_occludes = [&](unsigned retest, uint32_t first_packet) {
    for (unsigned lanes = retest; lanes; lanes &= lanes - 1) {
      const uint32_t k = uint32_t(__builtin_ctz(lanes));
      const uint32_t p = first_packet + k / Triangle4::kLanes;
      const uint32_t lane = k % Triangle4::kLanes;
      if (packets_[p].triangles >> lane & 1u) {
        TriangleHit th;
        const Corners c = corners(p, lane);
        if (intersect_sheared_triangle((*sheared4)->r, ray.tmax, c.p0, c.p1, c.p2, &th))
          return true;
      } else if (primitive_occludes(scene_, packets_[p].prim[lane], ray)) {
        return true;
      }
    }
    return false;
  };
  const uint32_t end = first + (count + Triangle4::kLanes - 1) / Triangle4::kLanes;
  for (uint32_t p = first; p < end;) {
    if (packets_[p].triangles == 0) {
      // Spheres only (a sphere's leaf of its own, as in a room with balls in it): straight
      // to Part 1's sphere test, with no shear to make and no lane test, whose every lane
      // would come back as a retest.
      if (retest_occludes(packets_[p].entries, p)) return true;
      p += 1;
      continue;
    }
    if (!*sheared4) *sheared4 = new (storage) ShearedRay4(ray);
    if (kPairPackets && p + 1 < end) {
      const LeafPacket &a = packets_[p], &b = packets_[p + 1];
      Triangle8Hits h;
      triangle8_intersect(a.tri, b.tri, **sheared4, ray.tmax, a.entries | unsigned(b.entries) << 4,
                          &h);
      if (h.hit & (a.triangles | unsigned(b.triangles) << 4)) return true;
      if (retest_occludes(h.retest, p)) return true;
      p += 2;
    } else {
      const LeafPacket& a = packets_[p];
      Triangle4Hits h;
      triangle4_intersect(a.tri, **sheared4, ray.tmax, a.entries, &h);
      if (h.hit & a.triangles) return true;
      if (retest_occludes(h.retest, p)) return true;
      p += 1;
    }
  }
  return false;
}

bool WideBvh::occluded(const Ray& ray) const {
  if (nodes_.empty() || !traceable(ray)) return false;
  // The root's test first, in a frame of its own: in a room most shadow rays enter none of its
  // children (they cross only the room's empty space: 64% of CBspheres_lambertian's), and for
  // them the walk's frame (its stack, the shear's storage, the registers it saves) was about a
  // fifth of their instructions.
  const Box4Ray box_ray(ray);
  alignas(32) float t_entry[WideNode::kWidth];
  const unsigned entered = intersect_node(nodes_[0], box_ray, ray.tmax, t_entry);
  return entered != 0 && occluded_below(ray, box_ray, 0, entered);
}

// Out of line, so that the root's test above keeps its small frame.
[[gnu::noinline]] bool WideBvh::occluded_below(const Ray& ray, const Box4Ray& box_ray,
                                               uint32_t from, unsigned entered) const {
  // The shear is made at the first packet of triangles the ray reaches: many shadow rays of a
  // room that get this far reach none (they cross only a sphere's box), and for them its setup
  // (a division, a lane of each value) would be wasted. (Raw storage, not
  // std::optional, which zeroed the whole 448-byte payload on every call.)
  alignas(ShearedRay4) unsigned char shear_storage[sizeof(ShearedRay4)];
  const ShearedRay4* sheared4 = nullptr;
  static_assert(std::is_trivially_destructible_v<ShearedRay4>, "left in its storage unended");
  // Any occluder will do: no distances kept, no sorting.
  StackEntry stack[kStackSize];
  int top = 0;
  const WideNode* node = &nodes_[from];
  unsigned mask = entered;
  while (true) {
    // The entered children of `node`, pushed (in the order of their slots).
    while (mask) {
      const int k = __builtin_ctz(mask);
      mask &= mask - 1;
      if (node->count[k] > 0)
        prefetch_lines(&packets_[node->child[k]], leaf_lines(node->count[k]));
      else
        prefetch_lines(&nodes_[node->child[k]], int(sizeof(WideNode) / 64));
      if (top == kStackSize) stack_overflow();
      stack[top++] = {node->child[k], node->count[k], 0.0f};
    }
    if (top == 0) return false;
    const StackEntry e = stack[--top];
    if (e.count > 0) {
      if (leaf_occludes(ray, e.child, e.count, &sheared4, shear_storage)) return true;
      continue;
    }
    node = &nodes_[e.child];
    alignas(32) float t_entry[WideNode::kWidth];
    mask = intersect_node(*node, box_ray, ray.tmax, t_entry);
  }
}

unsigned WideBvh::occluded_together(const Ray* rays, unsigned offered, unsigned* answered) const {
  const int first = __builtin_ctz(offered);
  unsigned blocked = 0, done = 0;
#if PT_ACCEL_PACKETS
  if (!nodes_.empty()) {
    const RayPacket8 packet(rays, offered);
    if (packet.lanes & (packet.lanes - 1)) {
      blocked = occluded_packet(rays, packet);
      done = packet.lanes;
    }
  }
#endif
  // The first ray is always answered: alone, where it cannot go with others (or is not
  // traceable, which occluded() answers).
  if (!(done >> first & 1u)) {
    blocked |= unsigned(occluded(rays[first])) << first;
    done |= 1u << first;
  }
  *answered = done;
  return blocked;
}

#if PT_ACCEL_PACKETS
unsigned WideBvh::occluded_packet(const Ray* rays, const RayPacket8& packet) const {
  const unsigned group = packet.lanes;
  // Each ray's shear, made at the first packet of triangles it reaches (as occluded() does).
  alignas(ShearedRay4) unsigned char shear_storage[8][sizeof(ShearedRay4)];
  const ShearedRay4* sheared[8] = {};
  // A node or leaf still to visit, and the rays that enter it.
  struct Entry {
    uint32_t child;
    uint32_t count;  ///< 0: `child` is a node; else a leaf of `count` entries from `child`
    unsigned rays;
  };
  Entry stack[kStackSize];
  int top = 0;
  stack[top++] = {0, 0, group};
  unsigned blocked = 0;  // rays found occluded, which need nothing more
  while (top > 0) {
    const Entry e = stack[--top];
    const unsigned active = e.rays & ~blocked;
    if (active == 0) continue;
    if (e.count > 0) {
      for (unsigned l = active; l; l &= l - 1) {
        const int j = __builtin_ctz(l);
        if (leaf_occludes(rays[j], e.child, e.count, &sheared[j], shear_storage[j]))
          blocked |= 1u << j;
      }
      if (blocked == group) return blocked;
      continue;
    }
    if (__builtin_popcount(active) <= 2) {
      // One or two rays left in this subtree: each one's own walk, as occluded() makes it, costs
      // less than the packet's bookkeeping (on CBbunny, a packet kept together down to its last
      // ray took 0.4 % more of the render's instructions than this, a packet at the root only
      // 0.7 % more).
      for (unsigned l = active; l; l &= l - 1) {
        const int j = __builtin_ctz(l);
        const Box4Ray box_ray(rays[j]);
        alignas(32) float t_entry[WideNode::kWidth];
        const unsigned entered = intersect_node(nodes_[e.child], box_ray, rays[j].tmax, t_entry);
        if (entered != 0 && occluded_below(rays[j], box_ray, e.child, entered)) blocked |= 1u << j;
      }
      if (blocked == group) return blocked;
      continue;
    }
    const WideNode& node = nodes_[e.child];
    // Which rays enter which children, by each ray's own test, so a ray reaches exactly the
    // leaves its single walk would. Where several rays are left, one test of the whole packet
    // first rules out the children none of them enters; then each child it leaves is tested
    // for all the rays at once, or each ray for all those children, whichever is fewer tests:
    // never more than the single walks' one test a ray.
    unsigned child_rays[WideNode::kWidth] = {};
    const int rays_left = __builtin_popcount(active);
    const unsigned may = rays_left > 1 ? packet_may_enter8(node.boxes, packet) : 0xFFu;
    if (may == 0) continue;
    if (__builtin_popcount(may) < rays_left) {
      for (unsigned m = may; m; m &= m - 1) {
        const int k = __builtin_ctz(m);
        child_rays[k] = rays_entering(node.boxes, k, packet) & active;
      }
    } else {
      for (unsigned l = active; l; l &= l - 1) {
        const int j = __builtin_ctz(l);
        for (unsigned m = ray_enters8(node.boxes, j, packet) & may; m; m &= m - 1)
          child_rays[__builtin_ctz(m)] |= 1u << j;
      }
    }
    for (unsigned m = may; m; m &= m - 1) {
      const int k = __builtin_ctz(m);
      if (child_rays[k] == 0) continue;
      if (node.count[k] > 0)
        prefetch_lines(&packets_[node.child[k]], leaf_lines(node.count[k]));
      else
        prefetch_lines(&nodes_[node.child[k]], int(sizeof(WideNode) / 64));
      if (top == kStackSize) stack_overflow();
      stack[top++] = {node.child[k], node.count[k], child_rays[k]};
    }
  }
  return blocked;
}
#endif

}  // namespace pt
