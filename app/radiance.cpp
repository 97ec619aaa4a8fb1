#include "app/radiance.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "framework/geometry/counting_ray_query.h"
#include "framework/lights/sampled_lights.h"
#include "framework/render/normal_shading.h"
#include "pipeline/4-global/integrator.h"
#ifdef PT_HAVE_WIDE_BVH
#include "app/accel/wide_bvh.h"
#endif
#ifdef PT_HAVE_FAST_LIGHTS
#include "app/fast/light_batches.h"
#endif

namespace pt {

std::vector<MaterialKind> rendered_material_kinds(const RenderSettings& settings) {
  if (settings.shading == ShadingMode::normals) return {};
  return {MaterialKind::diffuse, MaterialKind::mirror, MaterialKind::glass, MaterialKind::microfacet,
          MaterialKind::emission};
}

namespace {

#if defined(PT_HAVE_FAST_LIGHTS) && defined(PT_HAVE_WIDE_BVH)
// The wide tree as a camera sample's estimate asks it, with the shadow rays its light batch made
// answered from the packet the batch traces them in (LightBatches::occluded_answer); every other
// query, and a shadow ray the batch did not make, the tree answers alone.
class PacketShadowQuery final : public RayQuery {
 public:
  PacketShadowQuery(const WideBvh& bvh, LightBatches& batches) : bvh_(bvh), batches_(batches) {}
  bool intersect(const Ray& ray, SurfaceHit* hit) const override { return bvh_.intersect(ray, hit); }
  bool occluded(const Ray& ray) const override {
    bool blocked;
    if (batches_.occluded_answer(ray, &blocked)) return blocked;
    return bvh_.occluded(ray);
  }
  static unsigned trace(const void* bvh, const Ray* rays, unsigned offered, unsigned* answered) {
    return static_cast<const WideBvh*>(bvh)->occluded_together(rays, offered, answered);
  }

 private:
  const WideBvh& bvh_;
  LightBatches& batches_;
};
#endif

/// A camera sample's rays added to its tile's count: all of them, its camera ray and its shadow
/// rays (the counter's occlusion queries).
template <class Counting>
void count_kinds(const Counting& counting, TraceContext& context) {
  context.rays.add(counting.count());
  ++context.rays.camera;
  context.rays.shadow += counting.occluded_count();
}

// Every ray counts: each camera sample traces through a counter of its own, made on the stack
// around the render's query, and adds its count to the tile's context. Made for the query's own
// type where that is known (the wide tree, a final class), so a ray costs one virtual call into
// the counter, an increment and a direct call, and no thread-local lookup.
template <class Query>
TracedRadianceFn counted_radiance(const RenderSettings& settings, const Scene& scene,
                                  const Query& query, LightLayer layer) {
  if (settings.shading == ShadingMode::normals) {
    return [&query](const Ray& ray, Rng&, TraceContext& context) {
      const LocalCountingRayQuery<Query> counting(query);
      const glm::vec3 L = normal_shading(counting, ray);
      context.rays.add(counting.count());
      ++context.rays.camera;
      return L;
    };
  }
  std::string error;
  std::shared_ptr<Integrator> integrator = Integrator::create(settings, scene, query, &error);
  if (!integrator) throw std::runtime_error(error);
  auto trace = [integrator, &query](const Ray& ray, Rng& rng, TraceContext& context) {
    const LocalCountingRayQuery<Query> counting(query);
    const glm::vec3 L = integrator->radiance(ray, rng, counting);
    count_kinds(counting, context);
    return L;
  };
#ifdef PT_HAVE_FAST_LIGHTS
  if (layer == LightLayer::fast) {
    const int light_samples = std::max(1, settings.light_samples);
#ifdef PT_HAVE_WIDE_BVH
    if constexpr (std::is_same_v<Query, WideBvh>) {
      return [integrator, &query, light_samples](const Ray& ray, Rng& rng, TraceContext& context) {
        // As below, and the batch's shadow rays traced together, a packet a shading point.
        LightBatches batches(&rng, light_samples, ShadowRayTracer{&query, &PacketShadowQuery::trace});
        const FasterLightSampling::Installed installed(batches);
        const PacketShadowQuery packets(query, batches);
        const LocalCountingRayQuery<PacketShadowQuery> counting(packets);
        const glm::vec3 L = integrator->radiance(ray, rng, counting);
        count_kinds(counting, context);
        context.rays.packets += uint64_t(batches.packets_traced());
        context.rays.packet_rays += uint64_t(batches.packet_rays());
        return L;
      };
    }
#endif
    return [trace, light_samples](const Ray& ray, Rng& rng, TraceContext& context) {
      // The camera sample's light samples and shadow rays in lanes and batches, foreseen from the
      // generator its estimate draws from: the framework's definitions' answers, to the bit.
      LightBatches batches(&rng, light_samples);
      const FasterLightSampling::Installed installed(batches);
      return trace(ray, rng, context);
    };
  }
#else
  (void)layer;
#endif
  return trace;
}

}  // namespace

TracedRadianceFn make_radiance(const RenderSettings& settings, const Scene& scene,
                               const RayQuery& query, LightLayer layer) {
#ifdef PT_HAVE_WIDE_BVH
  if (const auto* wide = dynamic_cast<const WideBvh*>(&query))
    return counted_radiance(settings, scene, *wide, layer);
#endif
  return counted_radiance(settings, scene, query, layer);
}

std::string ray_kinds_line(const RenderReport& report) {
  const double per_s = report.seconds > 0.0 ? 1e-6 / report.seconds : 0.0;
  const uint64_t other = report.rays - std::min(report.rays, report.camera_rays + report.shadow_rays);
  char line[256];
  std::snprintf(line, sizeof line, "rays: camera %.1f, shadow %.1f, bounce and other %.1f M/s",
                double(report.camera_rays) * per_s, double(report.shadow_rays) * per_s,
                double(other) * per_s);
  std::string text = line;
  if (report.packets == 0) return text + "; no shadow packets";
  std::snprintf(line, sizeof line, "; shadow packets: %.0f %% of the shadow rays, %.1f rays a packet",
                report.shadow_rays > 0 ? 100.0 * double(report.packet_rays) / double(report.shadow_rays) : 0.0,
                double(report.packet_rays) / double(report.packets));
  return text + line;
}

std::string no_light_warning(const RenderSettings& settings, const Scene& scene) {
  if (settings.shading == ShadingMode::normals || !settings.environment_map.empty()) return "";
  // The integrator shows normals exactly when this set is empty.
  if (!SampledLights(scene, nullptr).lights().empty()) return "";
  return scene.source + ": nothing in the scene emits light (no light that can light it, no "
                        "emissive surface): rendering its shading normals instead of light";
}

}  // namespace pt
