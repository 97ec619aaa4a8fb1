#include "app/strategy_agreement.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "app/accelerator.h"
#include "app/render_job.h"
#include "framework/lights/sampled_lights.h"
#include "framework/render/film.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"

namespace pt {
namespace {

using nlohmann::json;

struct Strategy {
  const char* name;
  bool hemisphere;
  bool mis;
};
constexpr Strategy kStrategies[] = {
    {"light", false, false}, {"mis", false, true}, {"hemisphere", true, false}};

const char* unreachable_light(const SampledLight& l) {
  switch (l.kind) {
    case SampledLightKind::point: return "a point light";
    case SampledLightKind::spot: return "a spot light";
    case SampledLightKind::directional: return "a directional light";
    case SampledLightKind::parallelogram: return "an area light without a panel";
    default: return nullptr;
  }
}

std::string format_mean(const glm::dvec3& m) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.5g, %.5g, %.5g)", m.x, m.y, m.z);
  return buf;
}

}  // namespace

bool AgreementResult::agree() const {
  for (const StrategyComparison& c : comparisons)
    if (!c.test.pass) return false;
  return true;
}

std::string AgreementResult::summary() const {
  if (!skipped.empty()) return "skipped: " + skipped;
  std::string s;
  for (const StrategyRender& r : renders)
    s += r.strategy + " " + std::to_string(r.samples) + " spp mean " + format_mean(r.mean) + "; ";
  for (const StrategyComparison& c : comparisons)
    s += c.a + " vs " + c.b + ": " + (c.test.pass ? "same" : "DIFFER") + " (" + c.test.summary + "); ";
  if (!hemisphere_left_out.empty()) s += "hemisphere left out: " + hemisphere_left_out;
  return s;
}

std::string lights_hemisphere_cannot_see(const Scene& scene) {
  const SampledLights lights(scene);
  for (const SampledLight& l : lights.lights())
    if (const char* what = unreachable_light(l))
      return std::string("the scene has ") + what + ", which no ray can reach";
  return "";
}

AgreementResult compare_strategies(const Scene& scene, const AgreementOptions& options) {
  AgreementResult result;
  if (SampledLights(scene).lights().empty()) {
    result.skipped = "nothing in the scene emits (it renders its normals)";
    return result;
  }
  result.hemisphere_left_out = lights_hemisphere_cannot_see(scene);
  RenderSettings base;
  base.width = options.width;
  base.height = options.height;
  base.max_depth = options.max_depth;
  base.light_samples = options.light_samples;
  base.threads = options.threads;
  const std::unique_ptr<RayQuery> query = make_ray_query(base, scene);
  for (size_t i = 0; i < std::size(kStrategies); ++i) {
    const Strategy& strategy = kStrategies[i];
    if (strategy.hemisphere && !result.hemisphere_left_out.empty()) continue;
    RenderSettings s = base;
    s.hemisphere_sampling = strategy.hemisphere;
    s.mis = strategy.mis;
    s.samples_per_pixel = strategy.hemisphere
                              ? (options.hemisphere_samples > 0 ? options.hemisphere_samples
                                                                : 4 * options.samples)
                              : options.samples;
    s.seed = options.seed + i;
    Film film(s.width, s.height);
    const auto start = std::chrono::steady_clock::now();
    render_scene(s, scene, *query, &film);
    StrategyRender r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.strategy = strategy.name;
    r.samples = s.samples_per_pixel;
    r.estimate = film.estimate();
    for (const glm::vec3& m : r.estimate.mean) r.mean += glm::dvec3(m);
    r.mean /= double(std::max<size_t>(1, r.estimate.mean.size()));
    result.renders.push_back(std::move(r));
  }
  BlockTestOptions test;
  test.block_size = options.block_size;
  test.alpha = options.alpha;
  for (size_t a = 0; a < result.renders.size(); ++a)
    for (size_t b = a + 1; b < result.renders.size(); ++b)
      result.comparisons.push_back({result.renders[a].strategy, result.renders[b].strategy,
                                    block_t_test(result.renders[a].estimate,
                                                 result.renders[b].estimate, test)});
  return result;
}

json to_json(const AgreementResult& result) {
  json j;
  j["agree"] = result.agree();
  if (!result.skipped.empty()) j["skipped"] = result.skipped;
  if (!result.hemisphere_left_out.empty()) j["hemisphere_left_out"] = result.hemisphere_left_out;
  json renders = json::array();
  for (const StrategyRender& r : result.renders)
    renders.push_back({{"strategy", r.strategy},
                       {"samples_per_pixel", r.samples},
                       {"mean_radiance", {r.mean.x, r.mean.y, r.mean.z}},
                       {"seconds", r.seconds}});
  j["renders"] = renders;
  json comparisons = json::array();
  for (const StrategyComparison& c : result.comparisons) {
    const glm::vec3& ratio = c.test.overall_ratio;
    comparisons.push_back({{"a", c.a},
                           {"b", c.b},
                           {"same", c.test.pass},
                           {"blocks", c.test.blocks},
                           {"failing_blocks", c.test.failing.size()},
                           {"min_p_value", c.test.min_p_value},
                           {"mean_ratio", {ratio.x, ratio.y, ratio.z}},
                           {"summary", c.test.summary}});
  }
  j["comparisons"] = comparisons;
  return j;
}

BenchCommand add_agreement_command(CLI::App& bench) {
  struct State {
    std::vector<std::string> scenes;
    std::vector<int> resolution;
    AgreementOptions o;
  };
  auto s = std::make_shared<State>();
  AgreementOptions& o = s->o;
  CLI::App* app = bench.add_subcommand(
      "agreement", "light sampling, MIS and hemisphere sampling of each scene, compared pairwise "
                   "by the block t-test; JSON on stdout, exit 1 when a pair differs");
  app->add_option("scenes", s->scenes, "The scenes (COLLADA .dae)")->required()->expected(1, -1);
  app->add_option("-r,--resolution", s->resolution, "Width and height")->expected(2)->type_name("W H");
  app->add_option("-s,--samples", o.samples, "Samples per pixel of light sampling and MIS")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app->add_option("--hemisphere-samples", o.hemisphere_samples,
                  "Samples per pixel of hemisphere sampling (default: 4 x -s)")
      ->check(CLI::NonNegativeNumber);
  app->add_option("-m,--max-depth", o.max_depth, "Maximum ray depth")->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app->add_option("-l,--light-samples", o.light_samples, "Samples per area light")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app->add_option("--seed", o.seed, "Seed of the first strategy (the others take the next ones)")
      ->capture_default_str();
  app->add_option("-t,--threads", o.threads, "Render threads; 0 uses every core")->capture_default_str();
  app->add_option("--block-size", o.block_size, "Block size of the t-test")->capture_default_str()
      ->check(CLI::PositiveNumber);
  app->add_option("--alpha", o.alpha, "Family-wise significance of each comparison")
      ->capture_default_str()->check(CLI::Range(1e-12, 0.5));
  return {app, [s]() -> int {
            AgreementOptions& o = s->o;
            if (!s->resolution.empty()) {
              const int w = s->resolution[0], h = s->resolution[1];
              if (w < 1 || h < 1 || w > 16384 || h > 16384) {
                std::cerr << "bench agreement: -r: width and height must be between 1 and 16384\n";
                return 2;
              }
              o.width = w, o.height = h;
            }
            json out = json::array();
            bool all_agree = true;
            for (const std::string& path : s->scenes) {
              Scene scene;
              try {
                scene = load_collada(path);
              } catch (const SceneError& e) {
                std::cerr << "bench agreement: " << e.what() << "\n";
                return 1;
              }
              centre_camera_on(scene.bounds(), &scene.camera);  // as pathtracer places it
              std::cerr << "agreement: " << path << " ...\n";
              const AgreementResult r = compare_strategies(scene, o);
              std::cerr << "agreement: " << path << ": " << r.summary() << "\n";
              json j = to_json(r);
              j["scene"] = path;
              j["settings"] = {{"width", o.width},        {"height", o.height},
                               {"max_depth", o.max_depth}, {"light_samples", o.light_samples},
                               {"seed", o.seed},           {"block_size", o.block_size},
                               {"alpha", o.alpha}};
              out.push_back(j);
              all_agree = all_agree && r.agree();
            }
            std::cout << out.dump(2) << "\n";
            return all_agree ? 0 : 1;
          }};
}

}  // namespace pt
