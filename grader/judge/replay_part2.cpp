// Part 2's functions in a judge: each returns what the probe's record says the student's
// function returned for this call (record.h), so the test decides on the student's answers. The
// two walks' leaf tests are made again here, so what a walk found and the work it did are the
// judge's own.
#include <cstring>
#include <string>
#include <vector>

#include "grader/judge/replay.h"
#include "parts/2-bvh/bvh.h"
#include "parts/2-bvh/bvh_split.h"
#include "parts/2-bvh/ray_box.h"

namespace pt {
using judge::Cursor;
using judge::Fn;
using judge::JudgeCall;

bool intersect_box(const Bounds3&, const BoxRay&, float, float* t_entry) {
  const Fn fn = Fn::intersect_box;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  bool met = judge::get_bool(fn, out);
  if (judge::same_presence(fn, out, t_entry)) *t_entry = out.get<float>();
  judge::all_read(fn, out);
  return met;
}

MidpointSplit midpoint_split(const Bounds3&) {
  JudgeCall call(Fn::midpoint_split);
  Cursor& out = call.finish();
  MidpointSplit s = out.get<MidpointSplit>();
  judge::all_read(Fn::midpoint_split, out);
  return s;
}

SahSplit best_sah_split(const SahBin*, int, float, const SahCosts&) {
  JudgeCall call(Fn::best_sah_split);
  Cursor& out = call.finish();
  SahSplit s = out.get<SahSplit>();
  judge::all_read(Fn::best_sah_split, out);
  return s;
}

namespace {

/// The leaf of `nodes` whose primitives are [first, first + count), found through a map made
/// for the last tree asked about: the map is only a guess (the tree may have changed since), so
/// its answer is checked against the node, and the map made again when it is wrong.
const BvhNode* leaf_at(const std::vector<BvhNode>& nodes, uint32_t first, uint32_t count) {
  static std::vector<uint32_t> node_of_first;  // UINT32_MAX where no leaf starts
  auto fits = [&](uint32_t n) {
    return n < nodes.size() && nodes[n].is_leaf() && nodes[n].offset == first &&
           nodes[n].count == count;
  };
  auto guess = [&]() -> uint32_t {
    return first < node_of_first.size() ? node_of_first[first] : UINT32_MAX;
  };
  if (!fits(guess())) {
    node_of_first.clear();
    for (uint32_t n = 0; n < nodes.size(); ++n) {
      if (!nodes[n].is_leaf()) continue;
      if (nodes[n].offset >= node_of_first.size()) node_of_first.resize(nodes[n].offset + 1, UINT32_MAX);
      node_of_first[nodes[n].offset] = n;
    }
  }
  return fits(guess()) ? &nodes[guess()] : nullptr;
}

/// The node a recorded leaf test names: a leaf of this tree, or the record is refused.
const BvhNode& recorded_leaf(Fn fn, Cursor& args, const std::vector<BvhNode>& nodes) {
  const uint32_t first = args.get<uint32_t>(), count = args.get<uint32_t>();
  const BvhNode* leaf = leaf_at(nodes, first, count);
  if (!leaf)
    throw judge::RecordError(std::string("your ") + judge::name_of(fn) + " tested primitives " +
                             std::to_string(first) + " to " + std::to_string(first + count) +
                             " of the tree's order, which are not one leaf of it (leaf tests go "
                             "through intersect_leaf or leaf_occludes with the tree's own nodes)");
  return *leaf;
}

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace

// The walk's answer is the judge's: every leaf test the probe made is made again here, on this
// tree and this query's state, and counted here (the tree's counter and leaf log); the record's
// answers must be these, and the state the walk hands back must be the one they leave.
void Bvh::traverse_nearest(NearestState* state) const {
  const Fn fn = Fn::bvh_traverse_nearest;
  JudgeCall call(fn);
  Cursor& out = call.finish([&](int which, Cursor& args) {
    if (which != judge::kLeafTest)
      throw judge::RecordError("the record holds a callback Bvh::traverse_nearest does not make");
    intersect_leaf(recorded_leaf(fn, args, nodes_), state);
    Cursor answer = call.callback_answer();
    judge::expect_same_answer(fn, answer, state->best);
    judge::expect_same_answer(fn, answer, state->best_t);
    judge::expect_same_answer(fn, answer, state->cull.tmax);
    return answer;
  });
  const Ray cull = out.get<Ray>();
  const uint32_t best = out.get<uint32_t>();
  const float best_t = out.get<float>();
  const bool in_full = judge::get_bool(fn, out);
  const bool hit_made = judge::get_bool(fn, out);
  const SurfaceHit hit = out.get<SurfaceHit>();
  const TriangleHit best_triangle = out.get<TriangleHit>();
  judge::all_read(fn, out);
  if (best != state->best || !same_bits(best_t, state->best_t))
    throw judge::RecordError(
        "your Bvh::traverse_nearest reported " +
        (best == UINT32_MAX ? std::string("no hit") : "primitive " + std::to_string(best)) +
        ", but the leaves it tested through intersect_leaf give " +
        (state->found() ? "primitive " + std::to_string(state->best) : std::string("no hit")) +
        ": the nearest hit is what the leaf tests find, kept in the state they are handed");
  if (!same_bits(cull, state->cull) || in_full != state->in_full || hit_made != state->hit_made ||
      !same_bits(hit, state->hit) || !same_bits(best_triangle, state->best_triangle))
    throw judge::RecordError(
        "your Bvh::traverse_nearest changed the query's state other than through intersect_leaf");
}

bool Bvh::occluded(const Ray& ray) const {
  const Fn fn = Fn::bvh_occluded;
  JudgeCall call(fn);
  bool found = false;
  Cursor& out = call.finish([&](int which, Cursor& args) {
    if (which != judge::kLeafTest)
      throw judge::RecordError("the record holds a callback Bvh::occluded does not make");
    const BvhNode& leaf = recorded_leaf(fn, args, nodes_);
    const Ray tested = args.get<Ray>();
    const bool blocked = leaf_occludes(leaf, tested);
    found = found || (blocked && same_bits(tested, ray));
    Cursor answer = call.callback_answer();
    judge::expect_same_answer(fn, answer, uint8_t(blocked));
    return answer;
  });
  bool blocked = judge::get_bool(fn, out);
  judge::all_read(fn, out);
  if (blocked && !found)
    throw judge::RecordError(
        "your Bvh::occluded answered 'blocked', but no leaf it tested with leaf_occludes (with the "
        "ray it was asked about) found a blocker");
  return blocked;
}

}  // namespace pt
