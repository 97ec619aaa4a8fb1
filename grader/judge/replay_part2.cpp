// Part 2's functions in a judge: each returns what the probe's record says the student's
// function returned for this call (record.h), so the test decides on the student's answers.
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

void Bvh::traverse_nearest(NearestState* state) const {
  const Fn fn = Fn::bvh_traverse_nearest;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  state->cull = out.get<Ray>();
  state->best = out.get<uint32_t>();
  state->best_t = out.get<float>();
  state->in_full = judge::get_bool(fn, out);
  state->hit_made = judge::get_bool(fn, out);
  state->hit = out.get<SurfaceHit>();
  state->best_triangle = out.get<TriangleHit>();
  judge::all_read(fn, out);
  // The given code indexes the scene with the winner: one the scene does not have is no answer.
  if (state->best != UINT32_MAX && state->best >= scene_.primitive_count())
    throw judge::RecordError("your Bvh::traverse_nearest reported primitive " +
                             std::to_string(state->best) + " of a scene of " +
                             std::to_string(scene_.primitive_count()));
}

bool Bvh::occluded(const Ray&) const {
  const Fn fn = Fn::bvh_occluded;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  bool blocked = judge::get_bool(fn, out);
  judge::all_read(fn, out);
  return blocked;
}

}  // namespace pt
