// Do light sampling, MIS and hemisphere sampling render a scene as one image? The check that every
// strategy sees and samples the same emitters (bench agreement, and the test beside it).
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "app/bench_command.h"
#include "framework/image/render_estimate.h"
#include "framework/scene/scene.h"
#include "framework/stats/block_ttest.h"

namespace pt {

/// What each strategy renders. Hemisphere sampling is the noisiest, so it takes more samples.
struct AgreementOptions {
  int width = 160, height = 120;
  int samples = 1024;            ///< -s of light sampling and MIS
  int hemisphere_samples = 0;    ///< -s of hemisphere sampling; 0: 4 × samples
  int max_depth = 3;             ///< -m: the direct light of a few bounces, mirrors and glass
  int light_samples = 1;         ///< -l
  uint64_t seed = 1;             ///< strategy i renders with seed + i (independent estimates)
  int threads = 0;               ///< 0: every core
  int block_size = 16;           ///< of the block t-test
  double alpha = 1e-3;           ///< family-wise significance of each comparison
};

/// One strategy's render of the scene.
struct StrategyRender {
  std::string strategy;  ///< light, mis or hemisphere
  int samples = 0;
  glm::dvec3 mean{0.0};  ///< mean radiance over the image
  double seconds = 0.0;
  RenderEstimate estimate;
};

/// Two strategies' renders compared by the block t-test.
struct StrategyComparison {
  std::string a, b;
  BlockTestResult test;
};

struct AgreementResult {
  std::vector<StrategyRender> renders;
  std::vector<StrategyComparison> comparisons;
  /// Why hemisphere sampling was left out (the scene has a light no ray can reach), or "".
  std::string hemisphere_left_out;
  /// Why nothing was rendered (nothing in the scene emits), or "".
  std::string skipped;
  bool agree() const;
  /// One line a person can act on: each comparison's verdict and the means.
  std::string summary() const;
};

/// Why hemisphere sampling cannot render `scene` as light sampling does, or "" when it can: a
/// light no ray can reach (point, spot and directional lights, an area light without a panel)
/// is seen only by sampling it.
std::string lights_hemisphere_cannot_see(const Scene& scene);

/// Renders `scene` (its camera already placed) with light sampling, MIS and, where it can see
/// every light, hemisphere sampling, and compares each pair by the block t-test.
AgreementResult compare_strategies(const Scene& scene, const AgreementOptions& options);

nlohmann::json to_json(const AgreementResult& result);

/// `bench agreement SCENE...`: the subcommand, the check at full resolution, as JSON; exit 1
/// when a pair differs.
BenchCommand add_agreement_command(CLI::App& bench);

}  // namespace pt
