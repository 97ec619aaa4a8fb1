// The pathtracer command: load a COLLADA scene, render it tile by tile, write the image.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/accelerator.h"
#include "app/command_line.h"
#include "app/pixel_function.h"
#include "app/radiance.h"
#include "app/render_job.h"
#include "framework/image/image.h"
#include "framework/image/image_module_preload.h"
#include "framework/render/available_memory.h"
#include "framework/lights/sampled_lights.h"
#include "framework/render/film.h"
#include "framework/render/progress.h"
#include "framework/render/sample_rate.h"
#include "framework/render/tile_renderer.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/camera_settings_file.h"
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
    if (!std::filesystem::exists(settings.environment_map, ec))
      throw std::runtime_error("-e/--env " + settings.environment_map + ": no such file");
    if (!std::filesystem::is_regular_file(settings.environment_map, ec))
      throw std::runtime_error("-e/--env " + settings.environment_map +
                               ": not a regular file (a folder or a device?)");
  }

  // The film and its output buffers are the render's one image-sized cost: refused up front,
  // with the bytes, rather than a bare bad_alloc after the scene and its BVH are built (before
  // the scene is read when -r gives the size).
  auto check_memory = [&] {
    const uint64_t need = film_peak_bytes(settings.width, settings.height, command.output_path,
                                          settings.adaptive);
    const uint64_t have = available_memory_bytes();
    if (need > have)
      throw UsageError("-r/--resolution " + std::to_string(settings.width) + " " +
                       std::to_string(settings.height) + ": the image needs " +
                       std::to_string(need) + " bytes (" + describe_bytes(need) + ", " +
                       std::to_string(need / (uint64_t(settings.width) * uint64_t(settings.height))) +
                       " a pixel for its film and output) but only " + std::to_string(have) +
                       " bytes (" + describe_bytes(have) + ") are available");
  };
  if (command.resolution_given && !command.info) check_memory();

  Scene scene = load_collada(command.scene_path);
  if (command.info) {
    std::cout << describe_scene(scene) << describe_bvh(settings, scene);
    return kExitOk;
  }
  if (!command.resolution_given) {
    apply_default_resolution(scene.camera.aspect, &settings);
    check_cell(settings);
    check_memory();
  }
  if (!command.camera_settings_path.empty()) {
    // The course renderer's saved view replaces the file's camera, lens included, unless -b or
    // -d say otherwise.
    scene.camera = read_camera_settings(command.camera_settings_path, scene.camera);
    if (!command.lens_given) settings.lens_radius = scene.camera.lens_radius;
    if (!command.focal_distance_given) settings.focal_distance = scene.camera.focal_distance;
  }
  try {
    // A saved view (-c) stays where the course's renderer had it.
    const bool saved_view = !command.camera_settings_path.empty();
    if (command.camera_given)
      apply_camera_view(command.camera, &scene.camera);
    else if (command.course_view)
      place_course_camera(scene.bounds(), settings.width, settings.height, &scene.camera);
    else if (!command.file_camera && !saved_view)
      centre_camera_on(scene.bounds(), &scene.camera);
  } catch (const std::range_error& e) {
    throw SceneError(command.scene_path, "", e.what());
  }
  apply_lens(settings, &scene.camera);
  if (settings.shading == ShadingMode::light) {
    std::string fallback = materials_falling_back(scene, rendered_material_kinds(settings));
    if (!fallback.empty()) std::cerr << fallback << "\n";
    std::string dark = no_light_warning(settings, scene);
    if (!dark.empty()) std::cerr << "warning: " << dark << "\n";
    const SampledLights lights(scene);  // only for what it says; the render builds its own
    for (const std::string& w : lights.warnings())
      std::cerr << "warning: " << command.scene_path << ": " << w << "\n";
  }

  // The image module loads beside the BVH build and the render, not after the last ray; the
  // render's threads start first, or they would wait for the preload to open their libraries.
  start_render_threads(settings);
  ImageModulePreload image_module(command.output_path);
  std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
  Film film(settings.width, settings.height);
  TileRenderOptions options;
  options.progress = ProgressBar::stderr_is_terminal();
  RenderReport report = render_scene(settings, scene, *query, &film, options);
  std::cout << summary_line(report) << "\n" << ray_kinds_line(report) << "\n";

  image_module.wait();
  write_film(command.output_path, film);
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
  } catch (const std::bad_alloc&) {
    std::cerr << "pathtracer: out of memory (the scene and its BVH did not fit)\n";
    return pt::kExitIoError;
  } catch (const std::exception& e) {
    std::cerr << "pathtracer: " << e.what() << "\n";
    return pt::kExitIoError;
  } catch (...) {
    std::cerr << "pathtracer: unexpected error\n";
    return pt::kExitIoError;
  }
}
