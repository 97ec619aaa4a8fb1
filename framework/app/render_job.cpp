#include "render_job.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "1-raygen/pixel_loop.h"
#include "1-raygen/scene_intersect.h"
#include "2-bvh/bvh.h"
#include "4-global/integrator.h"
#include "5-adaptive/adaptive_sampling.h"
#ifdef PT_HAVE_WIDE_BVH
#include "accel/wide_bvh.h"
#endif
#include "geometry/counting_ray_query.h"

namespace pt {

namespace {

/// The binary tree's options the command line asked for (--bvh, --leaf-size).
BvhOptions bvh_options(const RenderSettings& settings) {
  BvhOptions options;
  options.split =
      settings.accel == AccelKind::bvh_median ? BvhSplitMethod::median : BvhSplitMethod::sah;
  options.max_leaf_size = settings.bvh_leaf_size;
  return options;
}

}  // namespace

std::unique_ptr<RayQuery> make_ray_query(const RenderSettings& settings, const Scene& scene) {
  if (settings.accel == AccelKind::brute_force) return std::make_unique<BruteForce>(scene);
  auto binary = std::make_unique<Bvh>(scene, bvh_options(settings));
#ifdef PT_HAVE_WIDE_BVH
  static_assert(kWideBvhWidth == WideNode::kWidth, "--bvh-width must name the wide tree's width");
  if (settings.bvh_width == kWideBvhWidth) return std::make_unique<WideBvh>(scene, *binary);
#endif
  return binary;  // --bvh-width 2, or a handout, which has no wide tree
}

std::string describe_bvh(const RenderSettings& settings, const Scene& scene) {
  if (settings.accel == AccelKind::brute_force) return "accelerator: none (brute force)\n";
  const Bvh binary(scene, bvh_options(settings));
  const BvhStats& s = binary.stats();
  char line[512];
  std::snprintf(line, sizeof line,
                "bvh: %s, leaf size %d: %u nodes, %u leaves (mean %.2f, max %u primitives), "
                "depth %u, SAH cost %.2f, built in %.1f ms\n",
                s.split == BvhSplitMethod::sah ? "sah" : "median", settings.bvh_leaf_size, s.nodes,
                s.leaves, s.mean_leaf_size, s.max_leaf_size, s.depth, s.sah_cost, s.build_ms);
  std::string text = line;
  if (settings.bvh_width == kWideBvhWidth) {
#ifdef PT_HAVE_WIDE_BVH
    const WideBvh wide(scene, binary);  // kept alive: stats() is a reference into it
    const WideBvhStats& w = wide.stats();
    std::snprintf(line, sizeof line,
                  "bvh width %d (traced): %u nodes (mean %.2f children), depth %u, collapsed in "
                  "%.1f ms\n",
                  kWideBvhWidth, w.nodes, w.mean_children, w.depth, w.build_ms);
    text += line;
#else
    text += "bvh width " + std::to_string(kWideBvhWidth) +
            ": not in this build (the handout); the binary tree above is traced\n";
#endif
  }
  return text;
}

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

void apply_lens(const RenderSettings& settings, Camera* camera) {
  camera->lens_radius = settings.lens_radius;
  if (settings.focal_distance > 0.0f) camera->focal_distance = settings.focal_distance;
}

PixelFn make_pixel_fn(const RenderSettings& settings, const Camera& camera,
                      const TracedRadianceFn& radiance) {
  AdaptiveSettings adaptive;
  adaptive.max_samples = settings.samples_per_pixel;
  adaptive.batch = settings.adaptive_batch;
  adaptive.tolerance = settings.adaptive_tolerance;
  return [&settings, &camera, &radiance, adaptive](int x, int y, Rng& rng, TraceContext& context,
                                                   PixelStats* stats) {
    RadianceFn sample = [&radiance, &context](const Ray& ray, Rng& r) {
      glm::vec3 L = radiance(ray, r, context);
      if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
        ++context.nonfinite_samples;
        return glm::vec3(0.0f);
      }
      return L;
    };
    PixelRef px{x, y, settings.width, settings.height};
    if (settings.adaptive)
      estimate_pixel_adaptive(camera, px, adaptive, rng, sample, stats);
    else
      estimate_pixel(camera, px, settings.samples_per_pixel, rng, sample, stats);
  };
}

RenderReport render_scene(const RenderSettings& settings, const Scene& scene,
                          const RayQuery& query, Film* film, const TileRenderOptions& options) {
  const TracedRadianceFn radiance = make_radiance(settings, scene, query);
  return render_tiles(settings, make_pixel_fn(settings, scene.camera, radiance), film, options);
}

}  // namespace pt
