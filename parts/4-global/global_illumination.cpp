// Part 4, step 1 (path): estimate_global_illumination; steps 2 (bounces) and 3
// (russian_roulette): at_least_one_bounce_radiance.
#include "parts/4-global/global_illumination.h"

#include <algorithm>
#include <cmath>

#include "framework/geometry/spawn_ray.h"
#include "framework/student/todo.h"
#include "parts/3-direct/direct_lighting.h"
#include "parts/4-global/mis.h"

namespace pt {

// Given, not a step: the choice between step 4's MIS and Part 3's estimate, as the settings ask.
glm::vec3 direct_radiance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng) {
  return ctx.mis ? estimate_direct_mis(ctx, sp, rng) : one_bounce_radiance(ctx, sp, rng);
}

glm::vec3 at_least_one_bounce_radiance(const LightingContext& ctx, const ShadingPoint& sp,
                                       int depth, Rng& rng) {
  // BEGIN SOLUTION
  const bool all = ctx.only_bounce < 0;
  const int last = all ? ctx.max_depth : std::min(ctx.max_depth, ctx.only_bounce);
  glm::vec3 L(0.0f);
  if (all || ctx.only_bounce == depth) L += direct_radiance(ctx, sp, rng);
  const bool specular = sp.bsdf->is_delta();
  if (depth > last || (depth == last && !specular)) return L;
  glm::vec3 wi;
  float pdf = 0.0f;
  glm::vec3 f = sp.bsdf->sample_f(sp.wo, rng.next_2d(), &wi, &pdf);
  if (!(pdf > 0.0f)) return L;
  glm::vec3 weight = f * std::abs(wi.z) / pdf;
  float q = 1.0f;
  if (ctx.russian_roulette && depth >= 2) {
    q = std::min(0.95f, std::max({weight.x, weight.y, weight.z}));
    if (!(q > 0.0f) || rng.next_float() >= q) return L;
  }
  Ray r = spawn_ray(sp.hit, sp.frame.to_world(wi));
  SurfaceHit h;
  const bool emission_counts = specular && (all || ctx.only_bounce == depth);
  glm::vec3 Li(0.0f);
  if (!ctx.query.intersect(r, &h)) {
    if (emission_counts) Li = ctx.lights.environment_radiance(r.d);
  } else {
    if (emission_counts) Li = zero_bounce_radiance(ctx, r, h);
    if (depth < last) Li += at_least_one_bounce_radiance(ctx, ShadingPoint(ctx.scene, r, h), depth + 1, rng);
  }
  return L + weight * Li / q;
  // END SOLUTION
  // STUDENT: the light leaving sp towards sp.wo after at least one bounce, sp being vertex
  // number `depth` of the path (the camera ray's hit is 1); docs/handout/part4.md has the idea.
  // In: sp, depth, ctx (max_depth -m, only_bounce --bounce, russian_roulette, mis, the lights and
  // the query); rng, the only source of random numbers. Out: radiance per channel, finite and
  // >= 0, whose expectation is the light of every path from sp of at most ctx.max_depth bounces
  // in all (with ctx.only_bounce = K >= 0: of exactly K bounces), each path counted once.
  // What must hold, and is graded:
  // - the light arriving at a vertex straight from the lights is direct_radiance's (given); after
  //   a diffuse vertex, an emitter the path meets adds nothing (that vertex's direct light counted
  //   it), after a specular one its emission, or the environment's, counts;
  // - a path goes on by one direction drawn from sp's BSDF, a ray made by spawn_ray, and what it
  //   brings back is weighted so that the expectation is right (glass sends light below the
  //   surface);
  // - step 3: with ctx.russian_roulette, a path may end at random from the second bounce on,
  //   never at the first, with a chance of going on that is above zero and below one at least
  //   sometimes, and the expectation stays what it is without roulette; without it no path ends
  //   before ctx.max_depth. Step 2's checks run with roulette off, step 3's compare your estimate
  //   with and without it;
  // - rng is the only source of random numbers, the roulette's coin included: the same sp, depth
  //   and an Rng in the same state give the same estimate (steps 2 and 3 each check it).
  PT_STUDENT_TODO("part 4", "at_least_one_bounce_radiance");
  (void)ctx, (void)sp, (void)depth, (void)rng;
  return glm::vec3(0.0f);
}

glm::vec3 estimate_global_illumination(const LightingContext& ctx, const Ray& ray, Rng& rng) {
  // BEGIN SOLUTION
  const bool zero_wanted = ctx.only_bounce <= 0;
  SurfaceHit hit;
  if (!ctx.query.intersect(ray, &hit))
    return zero_wanted ? ctx.lights.environment_radiance(ray.d) : glm::vec3(0.0f);
  glm::vec3 L = zero_wanted ? zero_bounce_radiance(ctx, ray, hit) : glm::vec3(0.0f);
  if (ctx.max_depth < 1 || ctx.only_bounce == 0) return L;
  return L + at_least_one_bounce_radiance(ctx, ShadingPoint(ctx.scene, ray, hit), 1, rng);
  // END SOLUTION
  // STUDENT: intersect the camera ray; if it escapes return the environment's radiance. Else
  // return zero_bounce_radiance plus (if ctx.max_depth >= 1) at_least_one_bounce_radiance of the
  // hit's ShadingPoint at depth 1. With ctx.only_bounce = K, keep only the K-bounce term.
  PT_STUDENT_TODO("part 4", "estimate_global_illumination");
  (void)ctx, (void)ray, (void)rng;
  return glm::vec3(0.0f);
}

}  // namespace pt
