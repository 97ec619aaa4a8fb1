#include "app/convergence.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/accelerator.h"
#include "app/pixel_function.h"
#include "app/radiance.h"
#include "app/render_job.h"
#include "framework/plot/convergence_plot.h"
#include "framework/render/film.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/collada_loader.h"
#include "framework/stats/image_error.h"

namespace pt {
namespace {

using nlohmann::json;

constexpr int kMaxResolution = 16384;

/// A direct-lighting estimator the study compares; adaptive sampling is added on top of the best.
struct Strategy {
  const char* name;
  bool hemisphere;
  bool mis;
};
constexpr Strategy kStrategies[] = {
    {"hemisphere", true, false}, {"light", false, false}, {"mis", false, true}};

RenderSettings with_strategy(RenderSettings s, const Strategy& strategy) {
  s.hemisphere_sampling = strategy.hemisphere;
  s.mis = strategy.mis;
  return s;
}

/// The scene loaded once, its camera placed as pathtracer places it, its BVH built once: each
/// render then times the tile loop only.
class StudyScene {
 public:
  explicit StudyScene(const std::string& path) : scene_(load_collada(path)) {
    centre_camera_on(scene_.bounds(), &scene_.camera);
    query_ = make_ray_query(RenderSettings{}, scene_);
  }
  const Scene& scene() const { return scene_; }

  RenderReport render(const RenderSettings& settings, Film* film) {
    apply_lens(settings, &scene_.camera);
    return render_scene(settings, scene_, *query_, film);
  }

  /// render(), also timing each pixel: *sample_cost gets each pixel's seconds per sample taken,
  /// row by row. Every pixel is rendered by one thread, so each entry has one writer; two clock
  /// reads a pixel are lost in the samples' time.
  RenderReport render_timed(const RenderSettings& settings, Film* film,
                            std::vector<double>* sample_cost) {
    apply_lens(settings, &scene_.camera);
    const int width = settings.width;
    sample_cost->assign(size_t(width) * size_t(settings.height), 0.0);
    const TracedRadianceFn radiance = make_radiance(settings, scene_, *query_);
    const PixelFn pixel = make_pixel_fn(settings, scene_.camera, radiance);
    const PixelFn timed = [&pixel, sample_cost, width](int x, int y, Rng& rng,
                                                       TraceContext& context, PixelStats* stats) {
      const long before = stats->count + stats->decision_samples;
      const auto start = std::chrono::steady_clock::now();
      pixel(x, y, rng, context, stats);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const long taken = std::max(1L, stats->count + stats->decision_samples - before);
      // A clock too coarse to see a pixel still must not make it free.
      (*sample_cost)[size_t(y) * size_t(width) + size_t(x)] = std::max(seconds, 1e-9) / double(taken);
    };
    return render_tiles(settings, timed, film);
  }

 private:
  Scene scene_;
  std::unique_ptr<RayQuery> query_;
};

void check_options(const ConvergenceOptions& o) {
  if (o.budgets.empty()) throw ConvergenceOptionError("--budgets: give at least one budget");
  for (size_t i = 0; i < o.budgets.size(); ++i) {
    if (o.budgets[i] < 1)
      throw ConvergenceOptionError("--budgets: every budget must be at least 1 sample per pixel (got " +
                                  std::to_string(o.budgets[i]) + ")");
    if (i > 0 && o.budgets[i] <= o.budgets[i - 1])
      throw ConvergenceOptionError("--budgets must grow: " + std::to_string(o.budgets[i]) +
                                  " follows " + std::to_string(o.budgets[i - 1]));
  }
  if (o.reference_spp < 1)
    throw ConvergenceOptionError("--reference-spp must be at least 1 (got " +
                                std::to_string(o.reference_spp) + ")");
  if (o.reference_seed == o.seed)
    throw ConvergenceOptionError("--reference-seed must differ from --seed (both " +
                                std::to_string(o.seed) +
                                "): a reference sharing the renders' random numbers flatters them");
  if (o.width < 1 || o.width > kMaxResolution || o.height < 0 || o.height > kMaxResolution)
    throw ConvergenceOptionError("-r: width and height must be between 1 and " +
                                std::to_string(kMaxResolution));
  if (o.max_depth < 0) throw ConvergenceOptionError("-m must be at least 0");
  if (o.light_samples < 1) throw ConvergenceOptionError("-l must be at least 1");
  if (o.threads < 0) throw ConvergenceOptionError("--threads must be 0 (every core) or more");
  if (o.adaptive_batch < 1 || !(o.adaptive_tolerance > 0.0f))
    throw ConvergenceOptionError("-a: BATCH must be at least 1 and TOL positive");
  if (!(o.target >= 0.0) || !std::isfinite(o.target))
    throw ConvergenceOptionError("--target must be a positive relMSE (or 0: automatic)");
}

double mean_samples(const Film& film) {
  return double(film.total_samples()) / (double(film.width()) * double(film.height()));
}

std::vector<ErrorPoint> points_of(const std::vector<ConvergenceMeasurement>& rows,
                                  const std::string& strategy) {
  std::vector<ErrorPoint> points;
  for (const ConvergenceMeasurement& r : rows)
    if (r.strategy == strategy) points.push_back({r.seconds, r.rel_mse});
  return points;
}

/// Least-squares slope of log relMSE against log samples over the larger half of a strategy's
/// rows (at least two): where the reference's noise and the first samples' bias matter least.
double error_slope(const std::vector<ConvergenceMeasurement>& rows, const std::string& strategy) {
  std::vector<std::pair<double, double>> xy;
  for (const ConvergenceMeasurement& r : rows)
    if (r.strategy == strategy && r.samples > 0.0 && r.rel_mse > 0.0)
      xy.push_back({std::log(r.samples), std::log(r.rel_mse)});
  if (xy.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  std::sort(xy.begin(), xy.end());
  xy.erase(xy.begin(), xy.begin() + std::min(xy.size() - 2, xy.size() / 2));
  double mx = 0.0, my = 0.0;
  for (const auto& p : xy) mx += p.first, my += p.second;
  mx /= double(xy.size()), my /= double(xy.size());
  double sxy = 0.0, sxx = 0.0;
  for (const auto& p : xy) {
    sxy += (p.first - mx) * (p.second - my);
    sxx += (p.first - mx) * (p.first - mx);
  }
  return sxx > 0.0 ? sxy / sxx : std::numeric_limits<double>::quiet_NaN();
}

std::string format(const char* fmt, double v) {
  char text[160];
  std::snprintf(text, sizeof text, fmt, v);
  return text;
}

}  // namespace

ConvergenceResult run_convergence(const ConvergenceOptions& o, std::ostream& log) {
  check_options(o);
  StudyScene study(o.scene_path);
  ConvergenceResult result;
  RenderSettings& base = result.base;
  base.width = o.width;
  const float aspect = study.scene().camera.aspect;
  base.height = o.height > 0 ? o.height
                             : int(std::clamp<long>(std::lround(float(o.width) /
                                                                (aspect > 0.0f && std::isfinite(aspect)
                                                                     ? aspect
                                                                     : 4.0f / 3.0f)),
                                                    1L, kMaxResolution));
  base.max_depth = o.max_depth;
  base.light_samples = o.light_samples;
  base.threads = o.threads;
  base.seed = o.seed;

  RenderSettings ref_settings = with_strategy(base, kStrategies[1]);
  ref_settings.samples_per_pixel = o.reference_spp;
  ref_settings.seed = o.reference_seed;
  ReferenceRenderer render_reference = [&study](const RenderSettings& s) {
    Film film(s.width, s.height);
    RenderReport report = study.render(s, &film);
    return ReferenceRender{film.estimate(), report.seconds};
  };
  result.reference = load_or_make_reference(o.scene_path, ref_settings, o.out_dir,
                                            render_reference, o.fresh_reference, log);
  const Image& reference = result.reference.image;

  // `estimate`, when given, receives the render's per-pixel estimate and `sample_cost` each
  // pixel's seconds per sample.
  auto measure = [&](const std::string& name, RenderSettings s, int budget,
                     RenderEstimate* estimate = nullptr, std::vector<double>* sample_cost = nullptr) {
    s.samples_per_pixel = budget;
    Film film(s.width, s.height);
    RenderReport report = sample_cost ? study.render_timed(s, &film, sample_cost)
                                      : study.render(s, &film);
    const Image image = film.mean_image();
    ConvergenceMeasurement m{name,
                             budget,
                             mean_samples(film),
                             report.seconds,
                             relative_mse(image, reference),
                             rmse(image, reference)};
    if (report.nonfinite_samples > 0)
      log << "warning: " << name << " at " << budget << " spp dropped "
          << report.nonfinite_samples << " non-finite samples to black\n";
    log << std::left << std::setw(16) << name << std::right << std::setw(6) << budget
        << format(" spp  %9.2f samples", m.samples) << format("  %9.3f s", m.seconds)
        << format("  relMSE %.4e", m.rel_mse) << format("  RMSE %.4e", m.rmse) << "\n"
        << std::flush;
    result.rows.push_back(m);
    if (estimate) *estimate = film.estimate();
    return m;
  };

  // The fixed-budget strategies, then adaptive sampling on the most efficient of them (lowest
  // relMSE × seconds at the largest budget: the one that reaches an error soonest).
  double best_efficiency = std::numeric_limits<double>::infinity();
  RenderSettings best_settings = base;
  RenderEstimate best_estimate;
  std::vector<double> best_cost;
  for (const Strategy& strategy : kStrategies) {
    ConvergenceMeasurement last;
    RenderEstimate last_estimate;
    std::vector<double> last_cost;
    for (int budget : o.budgets) {
      const bool largest = budget == o.budgets.back();
      last = measure(strategy.name, with_strategy(base, strategy), budget,
                     largest ? &last_estimate : nullptr, largest ? &last_cost : nullptr);
    }
    const double efficiency = last.rel_mse * last.seconds;
    if (efficiency < best_efficiency) {
      best_efficiency = efficiency;
      best_settings = with_strategy(base, strategy);
      result.adaptive_base = strategy.name;
      best_estimate = std::move(last_estimate);
      best_cost = std::move(last_cost);
    }
  }
  result.allocation_bound = relmse_allocation_bound(best_estimate, reference, best_cost);
  // Adaptive sampling only differs from uniform once the budget exceeds one batch.
  RenderSettings adaptive = best_settings;
  adaptive.adaptive = true;
  adaptive.adaptive_batch = o.adaptive_batch;
  adaptive.adaptive_tolerance = o.adaptive_tolerance;
  const std::string adaptive_name = "adaptive (" + result.adaptive_base + ")";
  bool any = false;
  for (int budget : o.budgets)
    if (budget > o.adaptive_batch) measure(adaptive_name, adaptive, budget), any = true;
  if (!any) measure(adaptive_name, adaptive, o.budgets.back());

  // The common target: light importance's error at its largest budget, unless one is given.
  if (o.target > 0.0) {
    result.target = o.target;
    result.target_source = "given by --target";
  } else {
    for (const ConvergenceMeasurement& r : result.rows)
      if (r.strategy == "light" && r.budget == o.budgets.back()) result.target = r.rel_mse;
    result.target_source = "light importance's at " + std::to_string(o.budgets.back()) + " spp";
  }
  std::vector<std::string> names;
  for (const ConvergenceMeasurement& r : result.rows)
    if (std::find(names.begin(), names.end(), r.strategy) == names.end()) names.push_back(r.strategy);
  const TimeToError light = time_to_error(points_of(result.rows, "light"), result.target);
  for (const std::string& name : names) {
    const std::vector<ErrorPoint> points = points_of(result.rows, name);
    StrategyTime t;
    t.strategy = name;
    t.time = time_to_error(points, result.target);
    double longest = 0.0;
    for (const ErrorPoint& p : points) longest = std::max(longest, p.seconds);
    if (t.time.extrapolated && t.time.seconds > kExtrapolationLimit * longest) {
      t.beyond_reach = true;
      t.time.seconds = std::numeric_limits<double>::quiet_NaN();
    }
    t.ratio_to_light = t.time.seconds / light.seconds;
    t.slope = error_slope(result.rows, name);
    result.times.push_back(t);
  }

  // Thread speed-up: one budget of light importance on one thread and on every thread, one
  // right after the other, so both see the same machine.
  if (o.speedup_budget >= 0) {
    const int budget = o.speedup_budget > 0 ? o.speedup_budget : o.budgets[o.budgets.size() / 2];
    RenderSettings s = with_strategy(base, kStrategies[1]);
    s.samples_per_pixel = budget;
    Film all_film(s.width, s.height), one_film(s.width, s.height);
    const std::clock_t cpu_start = std::clock();
    RenderReport all = study.render(s, &all_film);
    const double cpu_all = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    s.threads = 1;
    RenderReport one = study.render(s, &one_film);
    result.has_speedup = true;
    result.speedup = {budget, all.threads, one.seconds, all.seconds, cpu_all};
    log << "speed-up at " << budget << " spp (light): 1 thread " << format("%.3f s", one.seconds)
        << ", " << all.threads << " threads " << format("%.3f s", all.seconds)
        << format(": x%.2f", result.speedup.speedup())
        << format(" (%.2f cores busy)", result.speedup.cores_busy()) << "\n";
  }
  return result;
}

std::string convergence_report(const ConvergenceResult& r) {
  std::ostringstream s;
  const RenderSettings& b = r.base;
  s << "convergence: " << b.width << "x" << b.height << ", max depth " << b.max_depth
    << ", light samples " << b.light_samples << ", seed " << b.seed << "\n";
  s << "reference: " << r.reference.estimate.width << "x" << r.reference.estimate.height << ", "
    << (r.reference.reused ? "reused from " : "rendered to ") << r.reference.exr.string()
    << format(" (%.1f s to make)", r.reference.seconds)
    << format("; its own noise adds relMSE ~ %.2e to every row", r.reference.noise_rel_mse)
    << "\n";
  s << format("relMSE = mean over pixels and channels of (x - ref)^2 / (ref^2 + %g)\n",
              kRelMseEpsilon);
  s << "\n" << std::left << std::setw(18) << "strategy" << std::right << std::setw(8) << "budget"
    << std::setw(10) << "samples" << std::setw(11) << "seconds" << std::setw(13) << "relMSE"
    << std::setw(13) << "RMSE" << "\n";
  for (const ConvergenceMeasurement& m : r.rows)
    s << std::left << std::setw(18) << m.strategy << std::right << std::setw(8) << m.budget
      << format("%10.2f", m.samples) << format("%11.3f", m.seconds)
      << format("%13.4e", m.rel_mse) << format("%13.4e", m.rmse) << "\n";
  s << "\n" << format("time to reach relMSE %.4e", r.target) << " (" << r.target_source
    << "); [slope over the larger budgets: -1 unbiased, flatter means bias]:\n";
  for (const StrategyTime& t : r.times) {
    s << "  " << std::left << std::setw(18) << t.strategy << std::right;
    if (t.beyond_reach)
      s << format("  not reached: beyond %g x its longest render", kExtrapolationLimit);
    else if (std::isnan(t.time.seconds))
      s << "  not reached: its error does not fall to it";
    else
      s << format("%10.3f s", t.time.seconds)
        << (t.time.extrapolated ? " (extrapolated)" : "               ");
    if (std::isfinite(t.ratio_to_light)) s << format("  x%.3g light's time", t.ratio_to_light);
    s << format("   [relMSE ~ samples^%.2f]", t.slope) << "\n";
  }
  for (const StrategyTime& a : r.times)
    for (const StrategyTime& t : r.times)
      if (a.strategy == "adaptive (" + r.adaptive_base + ")" && t.strategy == r.adaptive_base &&
          std::isfinite(a.time.seconds / t.time.seconds))
        s << "  adaptive over uniform " << r.adaptive_base << ": "
          << format("x%.3g the time", a.time.seconds / t.time.seconds) << "\n";
  s << "  the best any per-pixel allocation can do (from uniform " << r.adaptive_base
    << "'s variance and time per pixel): "
    << format("x%.3g uniform's time", r.allocation_bound.best_time_fraction)
    << format(", x%.3g its samples", r.allocation_bound.best_sample_fraction)
    << format(" (%.1f%% of pixels have no variance)", 100.0 * r.allocation_bound.zero_variance_share)
    << "\n";
  if (r.has_speedup)
    s << "\nthread speed-up at " << r.speedup.budget << " spp (light): 1 thread "
      << format("%.3f s", r.speedup.seconds_one) << ", " << r.speedup.threads << " threads "
      << format("%.3f s", r.speedup.seconds_all) << format(": x%.2f", r.speedup.speedup())
      << format("; the all-thread render kept %.2f cores busy", r.speedup.cores_busy())
      << (r.speedup.cores_busy() < 0.8 * r.speedup.threads
              ? " (fewer than its threads: other work shared the machine, so the wall-time "
                "speed-up understates the renderer's)"
              : "")
      << "\n";
  return s.str();
}

std::vector<std::filesystem::path> write_convergence_outputs(const ConvergenceOptions& o,
                                                             const ConvergenceResult& r) {
  namespace fs = std::filesystem;
  fs::create_directories(o.out_dir);
  const fs::path csv = o.out_dir / "convergence.csv", js = o.out_dir / "convergence.json",
                 svg = o.out_dir / "convergence.svg";
  {
    std::ofstream out(csv);
    out << "strategy,samples,seconds,relMSE,RMSE,budget\n" << std::setprecision(9);
    for (const ConvergenceMeasurement& m : r.rows)
      out << m.strategy << ',' << m.samples << ',' << m.seconds << ',' << m.rel_mse << ','
          << m.rmse << ',' << m.budget << "\n";
    if (!out) throw std::runtime_error(csv.string() + ": cannot write");
  }
  json rows = json::array();
  std::vector<ConvergenceRow> plot_rows;
  for (const ConvergenceMeasurement& m : r.rows) {
    rows.push_back({{"strategy", m.strategy},
                    {"budget", m.budget},
                    {"samples", m.samples},
                    {"seconds", m.seconds},
                    {"relMSE", m.rel_mse},
                    {"RMSE", m.rmse}});
    plot_rows.push_back({m.strategy, m.samples, m.seconds, m.rel_mse, int(plot_rows.size()) + 2});
  }
  // JSON has no NaN: a figure that could not be told is null.
  auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json times = json::array();
  for (const StrategyTime& t : r.times) {
    times.push_back({{"strategy", t.strategy},
                     {"seconds", number(t.time.seconds)},
                     {"extrapolated", t.time.extrapolated},
                     {"beyond_reach", t.beyond_reach},
                     {"slope_relmse_vs_samples", number(t.slope)},
                     {"ratio_to_light", number(t.ratio_to_light)}});
  }
  json doc = {
      {"scene", o.scene_path},
      {"settings",
       {{"width", r.base.width},
        {"height", r.base.height},
        {"max_depth", r.base.max_depth},
        {"light_samples", r.base.light_samples},
        {"seed", r.base.seed},
        {"budgets", o.budgets},
        {"adaptive", {{"batch", o.adaptive_batch}, {"tolerance", o.adaptive_tolerance}}},
        {"adaptive_on", r.adaptive_base}}},
      {"rel_mse_epsilon", kRelMseEpsilon},
      {"reference",
       {{"exr", r.reference.exr.string()},
        {"manifest", r.reference.manifest.string()},
        {"key", r.reference.key},
        {"samples_per_pixel", o.reference_spp},
        {"seed", o.reference_seed},
        {"reused", r.reference.reused},
        {"seconds", r.reference.seconds},
        {"noise_rel_mse", r.reference.noise_rel_mse}}},
      {"rows", rows},
      {"target", {{"relMSE", r.target}, {"source", r.target_source}}},
      {"time_to_target", times},
      {"allocation_bound",
       {{"strategy", r.adaptive_base},
        {"best_sample_fraction", r.allocation_bound.best_sample_fraction},
        {"best_time_fraction", number(r.allocation_bound.best_time_fraction)},
        {"zero_variance_share", r.allocation_bound.zero_variance_share}}}};
  if (r.has_speedup)
    doc["speedup"] = {{"budget", r.speedup.budget},
                      {"strategy", "light"},
                      {"threads", r.speedup.threads},
                      {"seconds_1_thread", r.speedup.seconds_one},
                      {"seconds_all_threads", r.speedup.seconds_all},
                      {"speedup", r.speedup.speedup()},
                      {"cpu_seconds_all_threads", r.speedup.cpu_seconds_all},
                      {"cores_busy_all_threads", r.speedup.cores_busy()}};
  {
    std::ofstream out(js);
    out << doc.dump(2) << "\n";
    if (!out) throw std::runtime_error(js.string() + ": cannot write");
  }
  {
    const std::string title =
        "relMSE against render time: " + fs::path(o.scene_path).stem().string() + ", " +
        std::to_string(r.base.width) + "x" + std::to_string(r.base.height) + ", max depth " +
        std::to_string(r.base.max_depth);
    const std::string text = convergence_svg(plot_rows, PlotAxis::seconds, title, csv.filename().string());
    std::ofstream out(svg);
    out << text;
    if (!out) throw std::runtime_error(svg.string() + ": cannot write");
  }
  return {csv, js, svg};
}

BenchCommand add_convergence_command(CLI::App& bench) {
  struct State {
    ConvergenceOptions o;
    std::vector<int> resolution;
    std::vector<double> adaptive;
    std::string out_dir;
  };
  auto s = std::make_shared<State>();
  s->out_dir = s->o.out_dir.string();
  ConvergenceOptions& o = s->o;
  CLI::App* app = bench.add_subcommand(
      "convergence", "relMSE against render time for each sampling strategy (hemisphere, light "
                     "importance, MIS, adaptive on the best), against a cached high-sample "
                     "reference; writes convergence.csv, .json and .svg");
  app->add_option("scene", o.scene_path, "The scene (COLLADA .dae)")->required();
  app->add_option("--out", s->out_dir, "Folder of the table, the plot and the cached reference")
      ->capture_default_str();
  app->add_option("--budgets", o.budgets, "Samples per pixel of each render, growing, comma-separated")
      ->delimiter(',')->capture_default_str();
  app->add_option("--reference-spp", o.reference_spp, "Samples per pixel of the reference")
      ->capture_default_str();
  app->add_option("--seed", o.seed, "Seed of the measured renders")->capture_default_str();
  app->add_option("--reference-seed", o.reference_seed, "Seed of the reference (must differ)")
      ->capture_default_str();
  app->add_option("-r,--resolution", s->resolution,
                  "Width and height (default: 200 wide, the camera's aspect)")
      ->expected(2)->type_name("W H");
  app->add_option("-m,--max-depth", o.max_depth, "Maximum ray depth")->capture_default_str();
  app->add_option("-l,--light-samples", o.light_samples, "Samples per area light")
      ->capture_default_str();
  app->add_option("-t,--threads", o.threads, "Render threads; 0 uses every core")
      ->capture_default_str();
  app->add_option("-a,--adaptive", s->adaptive, "Adaptive strategy's BATCH and TOL (default 32 0.05)")
      ->expected(2)->type_name("BATCH TOL");
  app->add_option("--target", o.target,
                  "relMSE at which to compare times (default: light importance's at the largest "
                  "budget)");
  app->add_option("--speedup-budget", o.speedup_budget,
                  "Budget rendered on 1 thread too (0: the middle budget; -1: none)")
      ->capture_default_str();
  app->add_flag("--fresh-reference", o.fresh_reference,
                "Render the reference again even when the cached one matches (after a code change)");
  return {app, [s]() -> int {
            ConvergenceOptions& o = s->o;
            o.out_dir = s->out_dir;
            if (!s->resolution.empty()) o.width = s->resolution[0], o.height = s->resolution[1];
            if (!s->adaptive.empty()) {
              const double batch = s->adaptive[0];
              if (!(batch >= 1.0 && batch <= 1e6) || batch != std::floor(batch)) {
                std::cerr << "bench convergence: -a: BATCH must be a whole number of at least 1\n";
                return 2;
              }
              o.adaptive_batch = int(batch);
              o.adaptive_tolerance = float(s->adaptive[1]);
            }
            ConvergenceResult result;
            try {
              result = run_convergence(o, std::cerr);
            } catch (const ConvergenceOptionError& e) {
              std::cerr << "bench convergence: " << e.what() << "\n";
              return 2;
            }
            std::cout << convergence_report(result);
            for (const auto& path : write_convergence_outputs(o, result))
              std::cout << "wrote " << path.string() << "\n";
            return 0;
          }};
}

}  // namespace pt
