// Part 4's functions in a judge: each returns what the probe's record says the student's
// function returned for this call (record.h), so the test decides on the student's answers.
#include "grader/judge/replay.h"
#include "parts/4-global/global_illumination.h"
#include "parts/4-global/mis.h"

namespace pt {
using judge::Cursor;
using judge::Fn;
using judge::JudgeCall;

glm::vec3 direct_radiance(const LightingContext& ctx, const ShadingPoint&, Rng& rng) {
  return judge::replay_estimate(Fn::direct_radiance, ctx, rng);
}
glm::vec3 at_least_one_bounce_radiance(const LightingContext& ctx, const ShadingPoint&, int,
                                       Rng& rng) {
  return judge::replay_estimate(Fn::at_least_one_bounce_radiance, ctx, rng);
}
glm::vec3 estimate_global_illumination(const LightingContext& ctx, const Ray&, Rng& rng) {
  return judge::replay_estimate(Fn::estimate_global_illumination, ctx, rng);
}
float power_heuristic(int, float, int, float) {
  JudgeCall call(Fn::power_heuristic);
  Cursor& out = call.finish();
  float w = out.get<float>();
  judge::all_read(Fn::power_heuristic, out);
  return w;
}
glm::vec3 estimate_direct_mis(const LightingContext& ctx, const ShadingPoint&, Rng& rng) {
  return judge::replay_estimate(Fn::estimate_direct_mis, ctx, rng);
}

}  // namespace pt
