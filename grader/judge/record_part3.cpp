// Part 3's probe: each graded function of Part 3, recorded as the test calls it (record.h).
#include "grader/judge/record.h"
#include "grader/judge/recorded_query.h"
#include "grader/judge/wrap.h"
#include "parts/3-direct/diffuse_bsdf.h"
#include "parts/3-direct/direct_lighting.h"

#define DIFFUSE_F "_ZNK2pt11DiffuseBsdf1fERKN3glm3vecILi3EfLNS1_9qualifierE0EEES6_"
#define DIFFUSE_SAMPLE_F "_ZNK2pt11DiffuseBsdf8sample_fERKN3glm3vecILi3EfLNS1_9qualifierE0EEENS2_ILi2EfLS3_0EEEPS4_Pf"
#define DIFFUSE_PDF "_ZNK2pt11DiffuseBsdf3pdfERKN3glm3vecILi3EfLNS1_9qualifierE0EEES6_"
#define ZERO_BOUNCE_RADIANCE "_ZN2pt20zero_bounce_radianceERKNS_15LightingContextERKNS_3RayERKNS_10SurfaceHitE"
#define ESTIMATE_DIRECT_HEMISPHERE "_ZN2pt26estimate_direct_hemisphereERKNS_15LightingContextERKNS_16ShadingPointWithINS_11DiffuseBsdfEEERNS_3RngE"
#define ESTIMATE_DIRECT_IMPORTANCE "_ZN2pt26estimate_direct_importanceERKNS_15LightingContextERKNS_16ShadingPointWithINS_11DiffuseBsdfEEERNS_3RngE"
#define ONE_BOUNCE_RADIANCE "_ZN2pt19one_bounce_radianceERKNS_15LightingContextERKNS_16ShadingPointWithINS_11DiffuseBsdfEEERNS_3RngE"

namespace pt::judge {
namespace real {
glm::vec3 diffuse_f(const DiffuseBsdf*, const glm::vec3&, const glm::vec3&) PT_REAL(DIFFUSE_F);
glm::vec3 diffuse_sample_f(const DiffuseBsdf*, const glm::vec3&, glm::vec2, glm::vec3*, float*) PT_REAL(DIFFUSE_SAMPLE_F);
float diffuse_pdf(const DiffuseBsdf*, const glm::vec3&, const glm::vec3&) PT_REAL(DIFFUSE_PDF);
glm::vec3 zero_bounce_radiance(const LightingContext&, const Ray&, const SurfaceHit&) PT_REAL(ZERO_BOUNCE_RADIANCE);
glm::vec3 estimate_direct_hemisphere(const LightingContext&, const ShadingPoint&, Rng&) PT_REAL(ESTIMATE_DIRECT_HEMISPHERE);
glm::vec3 estimate_direct_importance(const LightingContext&, const ShadingPoint&, Rng&) PT_REAL(ESTIMATE_DIRECT_IMPORTANCE);
glm::vec3 one_bounce_radiance(const LightingContext&, const ShadingPoint&, Rng&) PT_REAL(ONE_BOUNCE_RADIANCE);
}  // namespace real

glm::vec3 wrap_diffuse_f(const DiffuseBsdf*, const glm::vec3&, const glm::vec3&) PT_WRAP(DIFFUSE_F);
glm::vec3 wrap_diffuse_f(const DiffuseBsdf* bsdf, const glm::vec3& wo, const glm::vec3& wi) {
  ProbeCall call(Fn::diffuse_f);
  glm::vec3 f = real::diffuse_f(bsdf, wo, wi);
  call.out.put(f);
  call.returned();
  return f;
}

glm::vec3 wrap_diffuse_sample_f(const DiffuseBsdf*, const glm::vec3&, glm::vec2, glm::vec3*, float*) PT_WRAP(DIFFUSE_SAMPLE_F);
glm::vec3 wrap_diffuse_sample_f(const DiffuseBsdf* bsdf, const glm::vec3& wo, glm::vec2 u,
                                glm::vec3* wi, float* pdf) {
  ProbeCall call(Fn::diffuse_sample_f);
  glm::vec3 f = real::diffuse_sample_f(bsdf, wo, u, wi, pdf);
  call.out.put(f);
  call.out.put(uint8_t(wi != nullptr));
  if (wi) call.out.put(*wi);
  call.out.put(uint8_t(pdf != nullptr));
  if (pdf) call.out.put(*pdf);
  call.returned();
  return f;
}

float wrap_diffuse_pdf(const DiffuseBsdf*, const glm::vec3&, const glm::vec3&) PT_WRAP(DIFFUSE_PDF);
float wrap_diffuse_pdf(const DiffuseBsdf* bsdf, const glm::vec3& wo, const glm::vec3& wi) {
  ProbeCall call(Fn::diffuse_pdf);
  float p = real::diffuse_pdf(bsdf, wo, wi);
  call.out.put(p);
  call.returned();
  return p;
}

glm::vec3 wrap_zero_bounce_radiance(const LightingContext&, const Ray&, const SurfaceHit&) PT_WRAP(ZERO_BOUNCE_RADIANCE);
glm::vec3 wrap_zero_bounce_radiance(const LightingContext& ctx, const Ray& ray, const SurfaceHit& hit) {
  ProbeCall call(Fn::zero_bounce_radiance);
  RecordedContext recorded(ctx, call, Fn::zero_bounce_radiance);
  glm::vec3 L = real::zero_bounce_radiance(recorded.get(), ray, hit);
  call.out.put(L);
  call.returned();
  return L;
}

/// The three estimators share a shape: radiance, and the generator as they leave it.
template <glm::vec3 (*Real)(const LightingContext&, const ShadingPoint&, Rng&)>
glm::vec3 record_estimate(Fn fn, const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  ProbeCall call(fn);
  RecordedContext recorded(ctx, call, fn);
  glm::vec3 L = Real(recorded.get(), sp, rng);
  call.out.put(L);
  call.out.put(rng);
  call.returned();
  return L;
}

glm::vec3 wrap_estimate_direct_hemisphere(const LightingContext&, const ShadingPoint&, Rng&) PT_WRAP(ESTIMATE_DIRECT_HEMISPHERE);
glm::vec3 wrap_estimate_direct_hemisphere(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  return record_estimate<real::estimate_direct_hemisphere>(Fn::estimate_direct_hemisphere, ctx, sp, rng);
}
glm::vec3 wrap_estimate_direct_importance(const LightingContext&, const ShadingPoint&, Rng&) PT_WRAP(ESTIMATE_DIRECT_IMPORTANCE);
glm::vec3 wrap_estimate_direct_importance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  return record_estimate<real::estimate_direct_importance>(Fn::estimate_direct_importance, ctx, sp, rng);
}
glm::vec3 wrap_one_bounce_radiance(const LightingContext&, const ShadingPoint&, Rng&) PT_WRAP(ONE_BOUNCE_RADIANCE);
glm::vec3 wrap_one_bounce_radiance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  return record_estimate<real::one_bounce_radiance>(Fn::one_bounce_radiance, ctx, sp, rng);
}

}  // namespace pt::judge
