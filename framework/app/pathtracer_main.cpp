// The pathtracer command: load a COLLADA scene, render it tile by tile, write the image.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "1-raygen/pixel_loop.h"
#include "1-raygen/scene_intersect.h"
#include "2-bvh/bvh.h"
#include "4-global/integrator.h"
#include "5-adaptive/adaptive_sampling.h"
#include "command_line.h"
#include "geometry/ray_query.h"
#include "image/estimate_exr.h"
#include "image/image.h"
#include "image/sample_rate.h"
#include "render/film.h"
#include "render/progress.h"
#include "render/tile_renderer.h"
#include "render/trace_context.h"
#include "scene/camera_placement.h"
#include "scene/collada_loader.h"
#include "scene/scene_error.h"
#include "scene/scene_summary.h"

namespace pt {
namespace {

/// The structure that answers the rays: Part 2's BVH (SAH or midpoint splits), or brute force.
std::unique_ptr<RayQuery> make_ray_query(const RenderSettings& settings, const Scene& scene) {
  if (settings.accel == AccelKind::brute_force) return std::make_unique<BruteForce>(scene);
  BvhOptions options;
  options.split =
      settings.accel == AccelKind::bvh_median ? BvhSplitMethod::median : BvhSplitMethod::sah;
  options.max_leaf_size = settings.bvh_leaf_size;
  return std::make_unique<Bvh>(scene, options);
}

/// The BVH's build statistics, for --info.
std::string describe_bvh(const RenderSettings& settings, const Scene& scene) {
  if (settings.accel == AccelKind::brute_force) return "accelerator: none (brute force)\n";
  const std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
  const BvhStats& s = static_cast<const Bvh&>(*query).stats();
  char line[256];
  std::snprintf(line, sizeof line,
                "bvh: %s, leaf size %d: %u nodes, %u leaves (mean %.2f, max %u primitives), "
                "depth %u, SAH cost %.2f, built in %.1f ms\n",
                s.split == BvhSplitMethod::sah ? "sah" : "median", settings.bvh_leaf_size, s.nodes,
                s.leaves, s.mean_leaf_size, s.max_leaf_size, s.depth, s.sah_cost, s.build_ms);
  return line;
}

/// The material kinds the lighting parts draw as the file asks.
std::vector<MaterialKind> rendered_material_kinds(const RenderSettings& settings) {
  if (settings.shading == ShadingMode::normals) return {};
  return {MaterialKind::diffuse, MaterialKind::mirror, MaterialKind::glass};
}

/// What a camera ray brings back: the normals view (--normals, or a scene with nothing that
/// emits), or the light Parts 3 and 4 estimate. The integrator lives as long as the function.
/// Only camera rays are counted: the integrator's shadow and bounce rays are not (yet).
TracedRadianceFn make_radiance(const RenderSettings& settings, const Scene& scene,
                               const RayQuery& query) {
  if (settings.shading == ShadingMode::normals) {
    return [&query](const Ray& ray, Rng&, TraceContext& context) {
      context.rays.add();
      return normal_shading(query, ray);
    };
  }
  std::string error;
  std::shared_ptr<Integrator> integrator = Integrator::create(settings, scene, query, &error);
  if (!integrator) throw std::runtime_error(error);
  return [integrator](const Ray& ray, Rng& rng, TraceContext& context) {
    context.rays.add();
    return integrator->radiance(ray, rng);
  };
}

/// Applies -b and -d to the scene's camera.
void apply_lens(const RenderSettings& settings, Camera* camera) {
  camera->lens_radius = settings.lens_radius;
  if (settings.focal_distance > 0.0f) camera->focal_distance = settings.focal_distance;
}

/// One pixel by Part 1's loop (or Part 5's with -a), dropping non-finite samples to black and
/// counting them, so the summary can say so.
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

int run(int argc, char** argv) {
  CommandLine command;
  int code = parse_command_line(argc, argv, &command, std::cout, std::cerr);
  if (code >= 0) return code;
  RenderSettings& settings = command.settings;

  if (!command.info) {
    if (command.output_path.empty())
      command.output_path = std::filesystem::path(command.scene_path).stem().string() + ".png";
    check_output_path(command.output_path);
  }
  if (!settings.environment_map.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(settings.environment_map, ec))
      throw std::runtime_error("-e/--env " + settings.environment_map + ": no such file");
  }

  Scene scene = load_collada(command.scene_path);
  if (command.info) {
    std::cout << describe_scene(scene) << describe_bvh(settings, scene);
    return kExitOk;
  }
  if (!command.resolution_given) {
    apply_default_resolution(scene.camera.aspect, &settings);
    check_cell(settings);
  }
  if (!command.file_camera) centre_camera_on(scene.bounds(), &scene.camera);
  apply_lens(settings, &scene.camera);
  if (settings.shading == ShadingMode::light) {
    std::string fallback = materials_falling_back(scene, rendered_material_kinds(settings));
    if (!fallback.empty()) std::cerr << fallback << "\n";
  }

  std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
  TracedRadianceFn radiance = make_radiance(settings, scene, *query);
  Film film(settings.width, settings.height);
  TileRenderOptions options;
  options.progress = ProgressBar::stderr_is_terminal();
  RenderReport report =
      render_tiles(settings, make_pixel_fn(settings, scene.camera, radiance), &film, options);
  std::cout << summary_line(report) << "\n";

  std::string ext = std::filesystem::path(command.output_path).extension().string();
  if (ext == ".exr" || ext == ".EXR")
    write_estimate_exr(command.output_path, film.estimate());
  else
    write_image(command.output_path, film.mean_image());
  std::cout << "wrote " << command.output_path << "\n";
  if (settings.adaptive) {
    // The course's NAME_rate.png beside the render: where the samples went.
    std::filesystem::path out(command.output_path);
    std::filesystem::path rate = out.parent_path() / (out.stem().string() + "_rate.png");
    write_image(rate.string(), sample_rate_image(film, settings.samples_per_pixel));
    std::cout << "wrote " << rate.string() << "\n";
  }
  return kExitOk;
}

}  // namespace
}  // namespace pt

int main(int argc, char** argv) {
  try {
    return pt::run(argc, argv);
  } catch (const pt::UsageError& e) {
    std::cerr << "pathtracer: " << e.what() << "\n";
    return pt::kExitUsage;
  } catch (const pt::SceneError& e) {
    std::cerr << "pathtracer: " << e.what() << "\n";
    return pt::kExitIoError;
  } catch (const pt::ImageError& e) {
    std::cerr << "pathtracer: " << e.what() << "\n";
    return pt::kExitIoError;
  } catch (const std::exception& e) {
    std::cerr << "pathtracer: " << e.what() << "\n";
    return pt::kExitIoError;
  } catch (...) {
    std::cerr << "pathtracer: unexpected error\n";
    return pt::kExitIoError;
  }
}
