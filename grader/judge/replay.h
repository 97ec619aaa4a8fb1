// What every judge's replay of a graded function does with the outputs the record holds.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "framework/sampling/rng.h"
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

/// An estimator's replay (Parts 3 and 4 share its shape): the radiance, and the generator as the
/// student's function left it.
inline glm::vec3 replay_estimate(Fn fn, Rng& rng) {
  JudgeCall call(fn);
  Cursor& out = call.finish();
  glm::vec3 L = out.get<glm::vec3>();
  rng = out.get<Rng>();
  all_read(fn, out);
  return L;
}

}  // namespace pt::judge
