#include "pipeline/4-global/integrator.h"

#include <cmath>

#include "parts/4-global/global_illumination.h"

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
  return in;
}

glm::vec3 Integrator::radiance(const Ray& ray, Rng& rng) const {
  if (normals_) return normal_shading(ctx_->query, ray);
  return estimate_global_illumination(*ctx_, ray, rng);
}

glm::vec3 normal_shading(const RayQuery& query, const Ray& ray) {
  SurfaceHit hit;
  if (!query.intersect(ray, &hit)) return glm::vec3(0.0f);
  glm::vec3 n = hit.n;
  if (!std::isfinite(n.x + n.y + n.z)) return glm::vec3(0.0f);
  return 0.5f * (n + glm::vec3(1.0f));
}

}  // namespace pt
