// The pathtracer command: load a COLLADA scene, render it tile by tile, write the image.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/accelerator.h"
#include "app/command_line.h"
#include "app/pixel_function.h"
#include "app/radiance.h"
#include "app/render_job.h"
#include "framework/image/estimate_exr.h"
#include "framework/image/image.h"
#include "framework/lights/light_set.h"
#include "framework/render/film.h"
#include "framework/render/progress.h"
#include "framework/render/sample_rate.h"
#include "framework/render/tile_renderer.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"
#include "framework/scene/scene_summary.h"

namespace pt {
namespace {

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
  if (command.course_view)
    place_course_camera(scene.bounds(), settings.width, settings.height, &scene.camera);
  else if (!command.file_camera)
    centre_camera_on(scene.bounds(), &scene.camera);
  apply_lens(settings, &scene.camera);
  if (settings.shading == ShadingMode::light) {
    std::string fallback = materials_falling_back(scene, rendered_material_kinds(settings));
    if (!fallback.empty()) std::cerr << fallback << "\n";
    const LightSet lights(scene);  // only for what it says; the render builds its own
    for (const std::string& w : lights.warnings())
      std::cerr << "warning: " << command.scene_path << ": " << w << "\n";
  }

  std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
  Film film(settings.width, settings.height);
  TileRenderOptions options;
  options.progress = ProgressBar::stderr_is_terminal();
  RenderReport report = render_scene(settings, scene, *query, &film, options);
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
