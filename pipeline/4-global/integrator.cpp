#include "pipeline/4-global/integrator.h"

#include <algorithm>

#include "framework/render/normal_shading.h"
#include "parts/4-global/global_illumination.h"
#include "pipeline/3-direct/direct_integrator.h"

namespace pt {

std::unique_ptr<Integrator> Integrator::create(const RenderSettings& settings, const Scene& scene,
                                               const RayQuery& query, std::string* error) {
  std::unique_ptr<Integrator> in(new Integrator());
  if (!settings.environment_map.empty()) {
    in->environment_ = std::make_unique<EnvironmentMap>();
    if (!in->environment_->load(settings.environment_map, error)) return nullptr;
  }
  in->lights_ = std::make_unique<LightSet>(scene, in->environment_.get());
  in->ctx_.reset(new LightingContext{scene, query, *in->lights_});
  LightingContext& c = *in->ctx_;
  c.light_samples = std::max(1, settings.light_samples);
  c.hemisphere = settings.hemisphere_sampling;
  c.mis = settings.mis;
  c.max_depth = std::max(0, settings.max_depth);
  c.russian_roulette = settings.russian_roulette;
  c.only_bounce = settings.only_bounce;
  in->normals_ = settings.shading == ShadingMode::normals || in->lights_->empty();
  switch (settings.integrator) {
    case IntegratorChoice::direct: in->direct_only_ = true; break;
    case IntegratorChoice::path: in->direct_only_ = false; break;
    case IntegratorChoice::automatic: in->direct_only_ = c.max_depth <= 1 && !c.mis; break;
  }
  return in;
}

namespace {

glm::vec3 estimate(const LightingContext& ctx, bool normals, bool direct_only, const Ray& ray,
                   Rng& rng) {
  if (normals) return normal_shading(ctx.query, ray);
  if (direct_only) return estimate_direct_illumination(ctx, ray, rng);
  return estimate_global_illumination(ctx, ray, rng);
}

}  // namespace

glm::vec3 Integrator::radiance(const Ray& ray, Rng& rng) const {
  return radiance(ray, rng, ctx_->query);
}

glm::vec3 Integrator::radiance(const Ray& ray, Rng& rng, const RayQuery& query) const {
  const LightingContext& c = *ctx_;
  // Every field of the context but the query, which a reference cannot be reseated to.
  LightingContext sample_context{c.scene, query, c.lights};
  sample_context.light_samples = c.light_samples;
  sample_context.hemisphere = c.hemisphere;
  sample_context.mis = c.mis;
  sample_context.max_depth = c.max_depth;
  sample_context.russian_roulette = c.russian_roulette;
  sample_context.only_bounce = c.only_bounce;
  return estimate(sample_context, normals_, direct_only_, ray, rng);
}

}  // namespace pt
