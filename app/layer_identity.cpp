#include "app/layer_identity.h"

#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/accelerator.h"
#include "app/render_job.h"
#include "framework/render/film.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"

namespace pt {
#ifdef PT_HAVE_FAST_LIGHTS
namespace {

// The settings each scene is rendered at: every way a light sample or shadow ray is asked for
// (light sampling at many samples a light, MIS, hemisphere sampling, adaptive sampling).
struct Variant {
  const char* name;
  int light_samples, max_depth;
  bool mis, hemisphere, adaptive;
};
constexpr Variant kVariants[] = {{"light -l 16 -m 5", 16, 5, false, false, false},
                                 {"mis -l 2 -m 6", 2, 6, true, false, false},
                                 {"hemisphere -l 1 -m 3", 1, 3, false, true, false},
                                 {"adaptive -a 16 0.05 -l 4 -m 4", 4, 4, false, false, true}};

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace
#endif

BenchCommand add_layers_command(CLI::App& bench) {
  struct State {
    std::vector<std::string> scenes;
    std::vector<int> resolution = {64, 48};
    int samples = 8, threads = 0;
    uint64_t seed = 5;
  };
  auto s = std::make_shared<State>();
  CLI::App* app = bench.add_subcommand(
      "layers", "each scene rendered with the fast layer's light samples and shadow rays and with "
                "the framework's definitions, at four settings, compared to the bit; exit 1 when "
                "a pixel differs");
  app->add_option("scenes", s->scenes, "The scenes (COLLADA .dae)")->required()->expected(1, -1);
  app->add_option("-r,--resolution", s->resolution, "Width and height (default 64 48)")
      ->expected(2)->type_name("W H")->check(CLI::Range(1, 4096));
  app->add_option("-s,--samples", s->samples, "Samples per pixel")->capture_default_str()
      ->check(CLI::Range(1, 1 << 16));
  app->add_option("--seed", s->seed, "Random seed")->capture_default_str();
  app->add_option("-t,--threads", s->threads, "Render threads; 0 uses every core")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  return {app, [s]() -> int {
#ifndef PT_HAVE_FAST_LIGHTS
            std::cerr << "bench layers: this build has no fast layer (app/fast): there is "
                         "nothing to compare\n";
            return 2;
#else
            int renders = 0, differ = 0;
            for (const std::string& path : s->scenes) {
              Scene scene;
              try {
                scene = load_collada(path);
              } catch (const SceneError& e) {
                std::cerr << "bench layers: " << e.what() << "\n";
                return 1;
              }
              centre_camera_on(scene.bounds(), &scene.camera);  // as pathtracer places it
              for (const Variant& v : kVariants) {
                RenderSettings settings;
                settings.width = s->resolution[0];
                settings.height = s->resolution[1];
                settings.samples_per_pixel = s->samples;
                settings.threads = s->threads;
                settings.seed = s->seed;
                settings.light_samples = v.light_samples;
                settings.max_depth = v.max_depth;
                settings.mis = v.mis;
                settings.hemisphere_sampling = v.hemisphere;
                settings.adaptive = v.adaptive;
                settings.adaptive_batch = 16;
                const std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
                Film fast(settings.width, settings.height), plain(settings.width, settings.height);
                render_scene(settings, scene, *query, &fast, {}, LightLayer::fast);
                render_scene(settings, scene, *query, &plain, {}, LightLayer::plain);
                const RenderEstimate a = fast.estimate(), b = plain.estimate();
                const bool same = same_bits(a.mean, b.mean) && same_bits(a.variance, b.variance) &&
                                  same_bits(a.count, b.count);
                ++renders;
                differ += same ? 0 : 1;
                std::cout << (same ? "same   " : "DIFFER ") << path << " [" << v.name << "]\n";
              }
            }
            std::cout << renders - differ << " of " << renders
                      << " renders the same to the bit with either layer\n";
            return differ == 0 ? 0 : 1;
#endif
          }};
}

}  // namespace pt
