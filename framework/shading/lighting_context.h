// The scene as the lighting functions see it (its ray queries and lights) and how they are asked
// to estimate (the settings of the estimator), handed to every function of Parts 3 and 4.
#pragma once

#include "framework/geometry/ray_query.h"
#include "framework/lights/light_set.h"
#include "framework/scene/scene.h"

namespace pt {

/// The scene, its ray queries and lights, and the estimator's settings.
struct LightingContext {
  const Scene& scene;
  const RayQuery& query;
  const LightSet& lights;
  int light_samples = 1;          ///< -l: samples per non-delta light (delta lights take one)
  bool hemisphere = false;        ///< -H: direct light by uniform hemisphere sampling
  bool mis = false;               ///< --mis: direct light by light and BSDF samples, weighted
  int max_depth = 1;              ///< -m: 0 emission only, 1 direct, 2 one indirect bounce, ...
  bool russian_roulette = true;   ///< end paths at random after the first bounce
  int only_bounce = -1;           ///< --bounce K: only light that took exactly K bounces
};

}  // namespace pt
