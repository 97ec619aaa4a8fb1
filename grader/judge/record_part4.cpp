// Part 4's probe: each graded function of Part 4, recorded as the test calls it (record.h).
#include "grader/judge/record.h"
#include "grader/judge/recorded_query.h"
#include "grader/judge/wrap.h"
#include "parts/4-global/global_illumination.h"
#include "parts/4-global/mis.h"

#define DIRECT_RADIANCE "_ZN2pt15direct_radianceERKNS_15LightingContextERKNS_16ShadingPointWithINS_11DiffuseBsdfEEERNS_3RngE"
#define AT_LEAST_ONE_BOUNCE_RADIANCE "_ZN2pt28at_least_one_bounce_radianceERKNS_15LightingContextERKNS_16ShadingPointWithINS_11DiffuseBsdfEEEiRNS_3RngE"
#define ESTIMATE_GLOBAL_ILLUMINATION "_ZN2pt28estimate_global_illuminationERKNS_15LightingContextERKNS_3RayERNS_3RngE"
#define POWER_HEURISTIC "_ZN2pt15power_heuristicEifif"
#define ESTIMATE_DIRECT_MIS "_ZN2pt19estimate_direct_misERKNS_15LightingContextERKNS_16ShadingPointWithINS_11DiffuseBsdfEEERNS_3RngE"

namespace pt::judge {
namespace real {
glm::vec3 direct_radiance(const LightingContext&, const ShadingPoint&, Rng&) PT_REAL(DIRECT_RADIANCE);
glm::vec3 at_least_one_bounce_radiance(const LightingContext&, const ShadingPoint&, int, Rng&) PT_REAL(AT_LEAST_ONE_BOUNCE_RADIANCE);
glm::vec3 estimate_global_illumination(const LightingContext&, const Ray&, Rng&) PT_REAL(ESTIMATE_GLOBAL_ILLUMINATION);
float power_heuristic(int, float, int, float) PT_REAL(POWER_HEURISTIC);
glm::vec3 estimate_direct_mis(const LightingContext&, const ShadingPoint&, Rng&) PT_REAL(ESTIMATE_DIRECT_MIS);
}  // namespace real

namespace {
glm::vec3 finish(ProbeCall& call, glm::vec3 L, const Rng& rng) {
  call.out.put(L);
  call.out.put(rng);
  call.returned();
  return L;
}
}  // namespace

glm::vec3 wrap_direct_radiance(const LightingContext&, const ShadingPoint&, Rng&) PT_WRAP(DIRECT_RADIANCE);
glm::vec3 wrap_direct_radiance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  ProbeCall call(Fn::direct_radiance);
  RecordedContext recorded(ctx, call, Fn::direct_radiance);
  return finish(call, real::direct_radiance(recorded.get(), sp, rng), rng);
}

glm::vec3 wrap_at_least_one_bounce_radiance(const LightingContext&, const ShadingPoint&, int, Rng&) PT_WRAP(AT_LEAST_ONE_BOUNCE_RADIANCE);
glm::vec3 wrap_at_least_one_bounce_radiance(const LightingContext& ctx, const ShadingPoint& sp,
                                            int depth, Rng& rng) {
  ProbeCall call(Fn::at_least_one_bounce_radiance);
  RecordedContext recorded(ctx, call, Fn::at_least_one_bounce_radiance);
  return finish(call, real::at_least_one_bounce_radiance(recorded.get(), sp, depth, rng), rng);
}

glm::vec3 wrap_estimate_global_illumination(const LightingContext&, const Ray&, Rng&) PT_WRAP(ESTIMATE_GLOBAL_ILLUMINATION);
glm::vec3 wrap_estimate_global_illumination(const LightingContext& ctx, const Ray& ray, Rng& rng) {
  ProbeCall call(Fn::estimate_global_illumination);
  RecordedContext recorded(ctx, call, Fn::estimate_global_illumination);
  return finish(call, real::estimate_global_illumination(recorded.get(), ray, rng), rng);
}

float wrap_power_heuristic(int, float, int, float) PT_WRAP(POWER_HEURISTIC);
float wrap_power_heuristic(int n_a, float pdf_a, int n_b, float pdf_b) {
  ProbeCall call(Fn::power_heuristic);
  float w = real::power_heuristic(n_a, pdf_a, n_b, pdf_b);
  call.out.put(w);
  call.returned();
  return w;
}

glm::vec3 wrap_estimate_direct_mis(const LightingContext&, const ShadingPoint&, Rng&) PT_WRAP(ESTIMATE_DIRECT_MIS);
glm::vec3 wrap_estimate_direct_mis(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  ProbeCall call(Fn::estimate_direct_mis);
  RecordedContext recorded(ctx, call, Fn::estimate_direct_mis);
  return finish(call, real::estimate_direct_mis(recorded.get(), sp, rng), rng);
}

}  // namespace pt::judge
