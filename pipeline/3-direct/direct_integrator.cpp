// Not needed for the assignment: the definitions of pipeline/3-direct/direct_integrator.h.
#include "pipeline/3-direct/direct_integrator.h"

#include <cmath>

#include "framework/geometry/spawn_ray.h"
#include "parts/3-direct/direct_lighting.h"

namespace pt {

glm::vec3 estimate_direct_illumination(const LightingContext& ctx, const Ray& ray, Rng& rng) {
  const bool zero_wanted = ctx.only_bounce <= 0;
  SurfaceHit hit;
  if (!ctx.query.intersect(ray, &hit))
    return zero_wanted ? ctx.lights.environment_radiance(ray.d) : glm::vec3(0.0f);
  glm::vec3 L = zero_wanted ? zero_bounce_radiance(ctx, ray, hit) : glm::vec3(0.0f);
  if (ctx.max_depth < 1 || ctx.only_bounce == 0 || ctx.only_bounce > 1) return L;
  const ShadingPoint sp(ctx.scene, ray, hit);
  L += one_bounce_radiance(ctx, sp, rng);
  if (!sp.bsdf->is_delta()) return L;
  // A mirror or glass: the light it passes on from the one direction it scatters into.
  glm::vec3 wi;
  float pdf = 0.0f;
  const glm::vec3 f = sp.bsdf->sample_f(sp.wo, rng.next_2d(), &wi, &pdf);
  if (!(pdf > 0.0f)) return L;
  const Ray r = spawn_ray(sp.hit, sp.frame.to_world(wi));
  SurfaceHit h;
  const glm::vec3 Le = ctx.query.intersect(r, &h) ? zero_bounce_radiance(ctx, r, h)
                                                  : ctx.lights.environment_radiance(r.d);
  return L + f * std::abs(wi.z) / pdf * Le;
}

}  // namespace pt
