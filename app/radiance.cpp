#include "app/radiance.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "framework/geometry/counting_ray_query.h"
#include "framework/render/normal_shading.h"
#include "pipeline/4-global/integrator.h"

namespace pt {

std::vector<MaterialKind> rendered_material_kinds(const RenderSettings& settings) {
  if (settings.shading == ShadingMode::normals) return {};
  return {MaterialKind::diffuse, MaterialKind::mirror, MaterialKind::glass, MaterialKind::emission};
}

// Every ray counts: the query is wrapped in a counter that the integrator traces through, and each
// camera sample adds what its path traced on this thread to the tile's context.
TracedRadianceFn make_radiance(const RenderSettings& settings, const Scene& scene,
                               const RayQuery& query) {
  auto counting = std::make_shared<CountingRayQuery>(query);
  if (settings.shading == ShadingMode::normals) {
    return [counting](const Ray& ray, Rng&, TraceContext& context) {
      const uint64_t before = counting->thread_count();
      const glm::vec3 L = normal_shading(*counting, ray);
      context.rays.add(counting->thread_count() - before);
      return L;
    };
  }
  std::string error;
  std::shared_ptr<Integrator> integrator = Integrator::create(settings, scene, *counting, &error);
  if (!integrator) throw std::runtime_error(error);
  return [integrator, counting](const Ray& ray, Rng& rng, TraceContext& context) {
    const uint64_t before = counting->thread_count();
    const glm::vec3 L = integrator->radiance(ray, rng);
    context.rays.add(counting->thread_count() - before);
    return L;
  };
}

}  // namespace pt
