// bench convergence: error against time for each sampling strategy of a scene, measured
// against a cached high-sample reference, as a table (CSV, JSON) and a log-log plot (SVG).
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/bench_command.h"
#include "app/reference_cache.h"
#include "framework/render/render_settings.h"
#include "framework/stats/allocation_bound.h"
#include "framework/stats/time_to_error.h"

namespace pt {

/// Options that cannot be honoured (a budget below 1, the reference's seed equal to the renders'):
/// a usage error, not a failure of the run.
struct ConvergenceOptionError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// What a convergence study renders. The defaults are the command line's.
struct ConvergenceOptions {
  std::string scene_path;
  std::filesystem::path out_dir = "out/convergence";
  std::vector<int> budgets = {1, 2, 4, 8, 16, 32, 64, 128, 256};  ///< samples per pixel
  int reference_spp = 4096;
  uint64_t seed = 1;                  ///< of every measured render
  uint64_t reference_seed = 1000003;  ///< of the reference: never the measured renders' seed
  int width = 200, height = 0;        ///< height 0: from the scene camera's aspect
  int max_depth = 5;
  int light_samples = 1;
  int threads = 0;                    ///< 0: every core
  int adaptive_batch = 32;            ///< -a BATCH of the adaptive strategy
  float adaptive_tolerance = 0.05f;   ///< -a TOL
  double target = 0.0;                ///< relMSE to compare times at; 0: light importance's last
  int speedup_budget = 0;             ///< budget timed on 1 thread too; 0: the middle one; <0: none
  bool fresh_reference = false;       ///< render the reference even when a cached one matches
};

/// One measured render.
struct ConvergenceMeasurement {
  std::string strategy;   ///< hemisphere, light, mis, adaptive (+ the base it refines)
  int budget = 0;         ///< -s: samples per pixel (the maximum, for adaptive)
  double samples = 0.0;   ///< mean samples per pixel actually taken
  double seconds = 0.0;   ///< wall time of the render only (no loading, no BVH build)
  double rel_mse = 0.0;
  double rmse = 0.0;
};

/// How long a strategy takes to reach the common target error.
struct StrategyTime {
  std::string strategy;
  TimeToError time;             ///< NaN seconds when not reached (see beyond_reach)
  double ratio_to_light = 0.0;  ///< its time / light importance's (NaN when either is unknown)
  /// The straight line through its last points reaches the target only beyond
  /// kExtrapolationLimit × its longest render: too far out to trust, so no time is given.
  bool beyond_reach = false;
  /// Log-log slope of relMSE against samples over its larger half of budgets: −1 for an unbiased
  /// estimator measured against a clean reference; flatter means a bias (or a noisy reference).
  double slope = 0.0;
};

/// How far past its longest render a strategy's time to the target may be extrapolated.
constexpr double kExtrapolationLimit = 4.0;

/// Render time of one budget on one thread and on every thread.
struct ThreadSpeedup {
  int budget = 0;
  int threads = 0;
  double seconds_one = 0.0, seconds_all = 0.0;
  /// Process CPU time of the all-thread render: cpu_all / seconds_all is how many cores it kept
  /// busy, which tells a renderer that does not scale from a machine others are using.
  double cpu_seconds_all = 0.0;
  double speedup() const { return seconds_all > 0.0 ? seconds_one / seconds_all : 0.0; }
  double cores_busy() const { return seconds_all > 0.0 ? cpu_seconds_all / seconds_all : 0.0; }
};

/// Everything a study measured.
struct ConvergenceResult {
  RenderSettings base;  ///< the settings every render shares (resolution, depth, seed)
  Reference reference;
  std::vector<ConvergenceMeasurement> rows;
  std::string adaptive_base;  ///< the strategy adaptive sampling was put on top of
  /// What any per-pixel allocation could save over uniform sampling of adaptive_base, from the
  /// per-pixel variances and times of its render at the largest budget: the ceiling adaptive
  /// sampling is measured against.
  AllocationBound allocation_bound;
  double target = 0.0;
  std::string target_source;  ///< how the target was chosen
  std::vector<StrategyTime> times;
  bool has_speedup = false;
  ThreadSpeedup speedup;
};

/// Renders the reference (or reuses it) and every strategy at every budget, printing each row
/// on `log` as it is measured. Throws SceneError for a scene that cannot be loaded and
/// ConvergenceOptionError for options that cannot be honoured.
ConvergenceResult run_convergence(const ConvergenceOptions& options, std::ostream& log);

/// Writes out_dir/convergence.csv (strategy,samples,seconds,relMSE,RMSE,budget), .json (the
/// settings, the reference, the rows, the times to the target, the speed-up) and .svg (relMSE
/// against seconds, log-log). Returns the paths written.
std::vector<std::filesystem::path> write_convergence_outputs(const ConvergenceOptions& options,
                                                             const ConvergenceResult& result);

/// The table and the time-to-target summary as a person reads them.
std::string convergence_report(const ConvergenceResult& result);

/// `bench convergence SCENE [options]`: the subcommand, which runs the study, prints the report
/// and writes the outputs.
BenchCommand add_convergence_command(CLI::App& bench);

}  // namespace pt
