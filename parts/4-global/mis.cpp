// Part 4, step 4 (mis): power_heuristic, estimate_direct_mis.
#include "parts/4-global/mis.h"

#include <algorithm>
#include <cmath>

#include "framework/geometry/spawn_ray.h"
#include "framework/student/todo.h"
#include "parts/3-direct/direct_lighting.h"

namespace pt {

float power_heuristic(int n_a, float pdf_a, int n_b, float pdf_b) {
  // BEGIN SOLUTION
  float a = float(n_a) * pdf_a, b = float(n_b) * pdf_b;
  if (std::isinf(a * a)) return 1.0f;
  float denom = a * a + b * b;
  return denom > 0.0f ? (a * a) / denom : 0.0f;
  // END SOLUTION
  // STUDENT: with a = n_a·pdf_a and b = n_b·pdf_b, return a² / (a² + b²); 0 when both are 0,
  // and 1 when a² overflows to infinity (a sample only strategy a could have drawn).
  PT_STUDENT_TODO("part 4", "power_heuristic");
  (void)n_a, (void)pdf_a, (void)n_b, (void)pdf_b;
  return 0.0f;
}

glm::vec3 estimate_direct_mis(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  // BEGIN SOLUTION
  if (sp.bsdf->is_delta()) return glm::vec3(0.0f);
  const auto& lights = ctx.lights.lights();
  const int ns = std::max(1, ctx.light_samples);
  glm::vec3 L(0.0f);
  for (int k = 0; k < int(lights.size()); ++k) {
    const int n = lights[k].is_delta() ? 1 : ns;
    glm::vec3 sum(0.0f);
    for (int i = 0; i < n; ++i) {
      LightSample ls = ctx.lights.sample(k, sp.hit, rng.next_2d());
      glm::vec3 wi = sp.frame.to_local(ls.wi);
      if (!(ls.pdf > 0.0f) || !(wi.z > 0.0f)) continue;
      glm::vec3 f = sp.bsdf->f(sp.wo, wi);
      if (f == glm::vec3(0.0f) || ls.L == glm::vec3(0.0f)) continue;
      if (!ctx.lights.unoccluded(ctx.query, spawn_shadow_ray(sp.hit, ls), k)) continue;
      float w = lights[k].can_be_hit() ? power_heuristic(n, ls.pdf, ns, sp.bsdf->pdf(sp.wo, wi)) : 1.0f;
      sum += f * ls.L * wi.z * (w / ls.pdf);
    }
    L += sum / float(n);
  }
  // BSDF samples: each ray brings back what every light it reaches sends along it.
  glm::vec3 sum(0.0f);
  for (int j = 0; j < ns; ++j) {
    glm::vec3 wi;
    float pdf_b = 0.0f;
    glm::vec3 f = sp.bsdf->sample_f(sp.wo, rng.next_2d(), &wi, &pdf_b);
    if (!(pdf_b > 0.0f) || !(wi.z > 0.0f) || f == glm::vec3(0.0f)) continue;
    Ray r = spawn_ray(sp.hit, sp.frame.to_world(wi));
    SurfaceHit h;
    const SurfaceHit* hit = ctx.query.intersect(r, &h) ? &h : nullptr;
    for (int k = 0; k < int(lights.size()); ++k) {
      if (!lights[k].can_be_hit()) continue;
      const glm::vec3 Le = ctx.lights.emitted_along(k, r, hit);
      if (Le == glm::vec3(0.0f)) continue;
      float pdf_l = ctx.lights.pdf(k, sp.hit, r.d, hit);
      if (!(pdf_l > 0.0f)) continue;  // a ray the light's own samples could never produce
      int n = lights[k].is_delta() ? 1 : ns;
      sum += f * Le * wi.z * (power_heuristic(ns, pdf_b, n, pdf_l) / pdf_b);
    }
  }
  return L + sum / float(ns);
  // END SOLUTION
  // STUDENT: the direct light reflected at sp towards sp.wo, estimated from light samples and
  // BSDF samples together, each weighted by the power heuristic (docs/handout/part4.md, step 4,
  // has the idea and the maths).
  // In: sp; ctx.lights (each light's samples, its density for a direction: pdf, what it sends
  // along a ray: emitted_along, whether a ray can hit it: can_be_hit), ctx.query,
  // ctx.light_samples (-l); rng, the only source of random numbers. Out: radiance per channel,
  // finite and >= 0, whose expectation is the direct-lighting integral at sp.
  // What must hold, and is graded:
  // - a specular BSDF gets nothing, and no ray is traced for it;
  // - the light samples are those of estimate_direct_importance (ctx.light_samples per area
  //   light, one per delta light), and ctx.light_samples directions come from sp.bsdf's own
  //   sampling, one ray each, meeting the lights as light sampling samples them;
  // - every sample of either strategy is weighted by power_heuristic against the density the
  //   other strategy, with its own sample count, gives the same direction (a light no ray can
  //   hit leaves its samples weight 1), so the estimate stays unbiased;
  // - rng is the only source of its random numbers: the same sp and an Rng in the same state give
  //   the same estimate.
  // Until then it returns no light (a stand-in that returned Part 3's estimate would pass the
  // step's known-answer checks without a line of MIS).
  PT_STUDENT_TODO("part 4", "estimate_direct_mis");
  (void)ctx, (void)sp, (void)rng;
  return glm::vec3(0.0f);
}

}  // namespace pt
