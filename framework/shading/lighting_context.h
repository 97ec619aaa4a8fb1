// What every function of Parts 3 and 4 is handed (ctx): the scene as the lighting functions see it
// (its ray query and lights) and how they are asked to estimate (the render's settings).
#pragma once

#include "framework/geometry/ray_query.h"
#include "framework/lights/light_set.h"
#include "framework/scene/scene.h"

namespace pt {

/// How a render asks the lighting functions to estimate, from its command line: given to the
/// render, never changed by it.
struct EstimatorSettings {
  int light_samples = 1;          ///< -l: samples per non-delta light (delta lights take one)
  bool hemisphere = false;        ///< -H: direct light by uniform hemisphere sampling
  bool mis = false;               ///< --mis: direct light by light and BSDF samples, weighted
  int max_depth = 1;              ///< -m: 0 emission only, 1 direct, 2 one indirect bounce, ...
  bool russian_roulette = true;   ///< end paths at random after the first bounce
  int only_bounce = -1;           ///< --bounce K: only light that took exactly K bounces
};

/// The scene, its ray query and lights (what the render built), and its settings
/// (ctx.light_samples, ctx.max_depth, ...).
struct LightingContext : EstimatorSettings {
  LightingContext(const Scene& s, const RayQuery& q, const LightSet& l,
                  const EstimatorSettings& settings = {})
      : EstimatorSettings(settings), scene(s), query(q), lights(l) {}

  const Scene& scene;
  const RayQuery& query;
  const LightSet& lights;
};

}  // namespace pt
