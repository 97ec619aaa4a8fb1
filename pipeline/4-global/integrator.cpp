// Not needed for the assignment: the definitions of pipeline/4-global/integrator.h.
#include "pipeline/4-global/integrator.h"

#include <algorithm>

#include "framework/render/normal_shading.h"
#include "parts/4-global/global_illumination.h"
#include "pipeline/3-direct/direct_integrator.h"

namespace pt {

namespace {

/// The estimator's settings from the render's: at least one light sample, no negative depth.
EstimatorSettings estimator_settings(const RenderSettings& settings) {
  EstimatorSettings e;
  e.light_samples = std::max(1, settings.light_samples);
  e.hemisphere = settings.hemisphere_sampling;
  e.mis = settings.mis;
  e.max_depth = std::max(0, settings.max_depth);
  e.russian_roulette = settings.russian_roulette;
  e.only_bounce = settings.only_bounce;
  return e;
}

glm::vec3 estimate(const LightingContext& ctx, bool normals, bool direct_only, const Ray& ray,
                   Rng& rng) {
  if (normals) return normal_shading(ctx.query, ray);
  if (direct_only) return estimate_direct_illumination(ctx, ray, rng);
  return estimate_global_illumination(ctx, ray, rng);
}

}  // namespace

std::unique_ptr<Integrator> Integrator::create(const RenderSettings& settings, const Scene& scene,
                                               const RayQuery& query, std::string* error) {
  std::unique_ptr<Integrator> in(new Integrator(scene, query));
  if (!settings.environment_map.empty()) {
    in->environment_ = std::make_unique<EnvironmentMap>();
    if (!in->environment_->load(settings.environment_map, error)) return nullptr;
  }
  in->lights_ = std::make_unique<LightSet>(scene, in->environment_.get());
  in->settings_ = estimator_settings(settings);
  in->normals_ = settings.shading == ShadingMode::normals || in->lights_->lights().empty();
  switch (settings.integrator) {
    case IntegratorChoice::direct: in->direct_only_ = true; break;
    case IntegratorChoice::path: in->direct_only_ = false; break;
    case IntegratorChoice::automatic:
      in->direct_only_ = in->settings_.max_depth <= 1 && !in->settings_.mis;
      break;
  }
  return in;
}

glm::vec3 Integrator::radiance(const Ray& ray, Rng& rng) const {
  return radiance(ray, rng, query_);
}

glm::vec3 Integrator::radiance(const Ray& ray, Rng& rng, const RayQuery& query) const {
  const LightingContext ctx(scene_, query, *lights_, settings_);
  return estimate(ctx, normals_, direct_only_, ray, rng);
}

}  // namespace pt
