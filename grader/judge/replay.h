// What every judge's replay of a graded function does with the outputs the record holds.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/sampling/rng.h"
#include "framework/shading/lighting_context.h"
#include "grader/judge/record.h"

namespace pt::judge {

/// A pointer argument the test passed (or not) must be one the probe saw passed (or not).
inline bool same_presence(Fn fn, Cursor& out, const void* p) {
  bool had = out.get<uint8_t>() != 0;
  if (had != (p != nullptr))
    throw RecordError(std::string("the record of ") + name_of(fn) +
                      " does not match the arguments the test passed");
  return had;
}

/// Every output read: a record with bytes left over is not one of this function.
inline void all_read(Fn fn, const Cursor& out) {
  if (!out.done())
    throw RecordError(std::string("the record of ") + name_of(fn) + " holds more than its outputs");
}

/// A bool as the record holds it: 0 or 1, anything else is no answer.
inline bool get_bool(Fn fn, Cursor& out) {
  uint8_t b = out.get<uint8_t>();
  if (b > 1) throw RecordError(std::string("the record of ") + name_of(fn) + " holds no bool");
  return b != 0;
}

/// The rays a call traced through its context's query (kQueryIntersect, kQueryOccluded), traced
/// again by the judge with `query` (the test's own, which counts them): the record's answer must
/// be the judge's. Any other callback is one the call does not make.
inline Cursor& replay_rays(JudgeCall& call, Fn fn, const RayQuery& query) {
  return call.finish([&](int which, Cursor& args) {
    const Ray ray = args.get<Ray>();
    all_read(fn, args);
    Cursor answer;
    if (which == kQueryIntersect) {
      SurfaceHit hit;
      const bool met = query.intersect(ray, &hit);
      answer = call.callback_answer();
      expect_same_answer(fn, answer, uint8_t(met));
      if (met) expect_same_answer(fn, answer, hit);
    } else if (which == kQueryOccluded) {
      const bool blocked = query.occluded(ray);
      answer = call.callback_answer();
      expect_same_answer(fn, answer, uint8_t(blocked));
    } else {
      throw RecordError(std::string("the record holds a callback ") + name_of(fn) +
                        " does not make");
    }
    all_read(fn, answer);
    return answer;
  });
}

/// An estimator's replay (Parts 3 and 4 share its shape): the rays it traced, the radiance, and
/// the generator as the student's function left it.
inline glm::vec3 replay_estimate(Fn fn, const LightingContext& ctx, Rng& rng) {
  JudgeCall call(fn);
  Cursor& out = replay_rays(call, fn, ctx.query);
  glm::vec3 L = out.get<glm::vec3>();
  rng = out.get<Rng>();
  all_read(fn, out);
  return L;
}

}  // namespace pt::judge
