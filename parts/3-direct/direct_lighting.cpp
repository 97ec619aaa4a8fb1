// Part 3, steps 2-5: zero_bounce_radiance (zero_bounce), estimate_direct_hemisphere
// (hemisphere), estimate_direct_importance (importance), one_bounce_radiance (one_bounce).
#include "parts/3-direct/direct_lighting.h"

#include <algorithm>

#include "framework/geometry/spawn_ray.h"
#include "framework/sampling/warp.h"
#include "framework/student/todo.h"

namespace pt {

glm::vec3 zero_bounce_radiance(const LightingContext& ctx, const Ray& ray, const SurfaceHit& hit) {
  // BEGIN SOLUTION
  const int light = ctx.lights.light_of_primitive(hit.primitive);
  if (light < 0) return glm::vec3(0.0f);
  return ctx.lights.emitted(light, hit, ray.d);
  // END SOLUTION
  // STUDENT: only the lights of ctx.lights glow, and what they send back is theirs to say, so
  // that the camera sees exactly the emitter that light sampling samples. Find the light the
  // hit belongs to (ctx.lights.light_of_primitive(hit.primitive); -1: the surface emits
  // nothing) and return ctx.lights.emitted(light, hit, ray.d): an area light's panel glows with
  // its light's radiance, on the light's side only. (This is what the camera, a mirror or glass
  // sees; the light a point receives is its light's own rectangle, which light sampling samples.)
  PT_STUDENT_TODO("part 3", "zero_bounce_radiance");
  (void)ctx, (void)ray, (void)hit;
  return glm::vec3(0.0f);
}

glm::vec3 estimate_direct_hemisphere(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  // BEGIN SOLUTION
  const int n = std::max(1, ctx.light_samples);
  glm::vec3 sum(0.0f);
  for (int i = 0; i < n; ++i) {
    glm::vec3 wi = square_to_uniform_hemisphere(rng.next_2d());
    Ray r = spawn_ray(sp.hit, sp.frame.to_world(wi));
    SurfaceHit h;
    const glm::vec3 Le = ctx.lights.radiance_along(r, ctx.query.intersect(r, &h) ? &h : nullptr);
    sum += sp.bsdf->f(sp.wo, wi) * Le * wi.z / uniform_hemisphere_pdf(wi);
  }
  return sum / float(n);
  // END SOLUTION
  // STUDENT: the direct light reflected at sp towards sp.wo, estimated from directions drawn
  // uniformly over the hemisphere above the surface (docs/handout/part3.md, step 3, has the idea
  // and the maths).
  // In: sp (its hit, local frame, wo and BSDF); ctx.query (what a ray hits), ctx.lights (what it
  // brings back: radiance_along), ctx.light_samples (-l); rng, the only source of random numbers.
  // Out: radiance per channel, finite and >= 0, whose expectation is the direct-lighting integral
  // at sp.
  // What must hold, and is graded:
  // - the estimate is the mean over ctx.light_samples directions, each drawn uniformly over the
  //   hemisphere (warp.h) and weighted by the density it was drawn with;
  // - each direction stands for a ray that leaves the hit (spawn_ray) in the world direction it
  //   stands for; f and cosθ are taken in sp's local frame;
  // - what a ray brings back is ctx.lights.radiance_along for it: the lights as light sampling
  //   samples them (an area light's own rectangle, not the panel the camera sees), the
  //   environment where it escapes, nothing from any other surface;
  // - rng is the only source of its random numbers: the same sp and an Rng in the same state give
  //   the same estimate.
  PT_STUDENT_TODO("part 3", "estimate_direct_hemisphere");
  (void)ctx, (void)sp, (void)rng;
  return glm::vec3(0.0f);
}

glm::vec3 estimate_direct_importance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  // BEGIN SOLUTION
  glm::vec3 L(0.0f);
  const auto& lights = ctx.lights.lights();
  for (int k = 0; k < int(lights.size()); ++k) {
    const int n = lights[k].is_delta() ? 1 : std::max(1, ctx.light_samples);
    glm::vec3 sum(0.0f);
    for (int i = 0; i < n; ++i) {
      LightSample ls = ctx.lights.sample(k, sp.hit, rng.next_2d());
      glm::vec3 wi = sp.frame.to_local(ls.wi);
      if (!(ls.pdf > 0.0f) || !(wi.z > 0.0f)) continue;
      glm::vec3 f = sp.bsdf->f(sp.wo, wi);
      if (f == glm::vec3(0.0f) || ls.L == glm::vec3(0.0f)) continue;  // no shadow ray for nothing
      if (ctx.lights.unoccluded(ctx.query, spawn_shadow_ray(sp.hit, ls), k))
        sum += f * ls.L * wi.z / ls.pdf;
    }
    L += sum / float(n);
  }
  return L;
  // END SOLUTION
  // STUDENT: the direct light reflected at sp towards sp.wo, estimated by sampling the lights
  // (docs/handout/part3.md, step 4, has the idea and the maths).
  // In: sp (its hit, local frame, wo and BSDF); ctx.lights (what each light is and its samples,
  // light_set.h), ctx.query (for visibility), ctx.light_samples (-l); rng, the only source of
  // random numbers. Out: radiance per channel, finite and >= 0, whose expectation is the
  // direct-lighting integral at sp.
  // What must hold, and is graded:
  // - every light adds its own light: the result is a sum over ctx.lights.lights() of each
  //   light's estimate, and a light's estimate is the mean of its own samples;
  // - an area light takes exactly ctx.light_samples samples, a delta light exactly one, whatever
  //   -l says; a sample's density is the one the LightSet gives it (per solid angle at sp);
  // - a sample adds light only from above the surface, with a density above zero, and only when
  //   nothing blocks it: one shadow ray per sample, made by spawn_shadow_ray (no offset of your
  //   own), and none for a sample that can add nothing (f or its radiance zero);
  // - directions are in the frame each quantity needs (f and cosθ in sp's local frame);
  // - rng is the only source of its random numbers: the same sp and an Rng in the same state give
  //   the same estimate.
  PT_STUDENT_TODO("part 3", "estimate_direct_importance");
  (void)ctx, (void)sp, (void)rng;
  return glm::vec3(0.0f);
}

glm::vec3 one_bounce_radiance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  // BEGIN SOLUTION
  if (sp.bsdf->is_delta()) return glm::vec3(0.0f);
  return ctx.hemisphere ? estimate_direct_hemisphere(ctx, sp, rng)
                        : estimate_direct_importance(ctx, sp, rng);
  // END SOLUTION
  // STUDENT: zero for a specular BSDF (sp.bsdf->is_delta()); otherwise the hemisphere estimate
  // if ctx.hemisphere, else the importance one.
  // The surface's own emission is not added here: it is zero_bounce_radiance's, counted once
  // where it is seen.
  PT_STUDENT_TODO("part 3", "one_bounce_radiance");
  (void)ctx, (void)sp, (void)rng;
  return glm::vec3(0.0f);
}

}  // namespace pt
