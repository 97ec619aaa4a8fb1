// Not needed for the assignment: the definitions of framework/lights/light_set.h.
// LightSet's answers: SampledLights' definitions, or those of the FasterLightSampling the calling
// thread installed (which must give the same bits).
#include "framework/lights/light_set.h"

#include "framework/lights/faster_light_sampling.h"
#include "framework/lights/sampled_lights.h"

namespace pt {

LightSet::LightSet(const Scene& scene, const EnvironmentMap* environment)
    : sampled_(std::make_unique<const SampledLights>(scene, environment)) {
  for (const SampledLight& l : sampled_->lights()) {
    LightTraits t;
    t.delta = l.is_delta();
    t.hittable = l.can_be_hit();
    traits_.push_back(t);
  }
}

LightSet::~LightSet() = default;
LightSet::LightSet(LightSet&&) noexcept = default;

LightSample LightSet::sample(int index, const SurfaceHit& hit, glm::vec2 u) const {
  if (FasterLightSampling* faster = FasterLightSampling::on_this_thread())
    return faster->sample(*sampled_, index, hit, u);
  return sampled_->make_sample(index, hit, u);
}

float LightSet::pdf(int index, const SurfaceHit& hit, const glm::vec3& wi,
                    const SurfaceHit* on_light) const {
  return sampled_->pdf(index, hit, wi, on_light);
}

int LightSet::light_of_primitive(uint32_t primitive) const {
  return sampled_->light_of_primitive(primitive);
}

glm::vec3 LightSet::emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const {
  return sampled_->emitted(index, on_light, wi);
}

glm::vec3 LightSet::emitted_along(int index, const Ray& ray, const SurfaceHit* hit) const {
  return sampled_->emitted_along(index, ray, hit);
}

glm::vec3 LightSet::radiance_along(const Ray& ray, const SurfaceHit* hit) const {
  return sampled_->radiance_along(ray, hit);
}

glm::vec3 LightSet::environment_radiance(const glm::vec3& dir) const {
  return sampled_->environment_radiance(dir);
}

bool LightSet::unoccluded(const RayQuery& query, const Ray& ray, int index) const {
  return sampled_->unoccluded(query, ray, index);
}

Ray spawn_shadow_ray(const SurfaceHit& hit, const LightSample& ls) {
  if (FasterLightSampling* faster = FasterLightSampling::on_this_thread())
    return faster->shadow_ray(hit, ls);
  return make_shadow_ray(hit, ls);
}

}  // namespace pt
