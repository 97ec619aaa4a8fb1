// Not needed for the assignment.
// Everything a render is asked to do, as the pathtracer command line states it.
#pragma once

#include <cstdint>
#include <string>

#include "framework/render/stopping_rule.h"

namespace pt {

/// Children a node of the wide BVH (app/accel) has: the --bvh-width that asks
/// for it. Stated here because the settings cannot see that solution-only library.
constexpr int kWideBvhWidth = 8;

/// Which acceleration structure answers the rays.
enum class AccelKind { bvh_sah, bvh_median, brute_force };

/// What the image shows: light (the full estimator), or the debug view of surface normals
/// (what the course's renderer shows before lighting exists).
enum class ShadingMode { light, normals };

/// Which estimator answers a camera ray (--integrator). `automatic` picks the normals view for
/// --normals, direct light alone for -m 0 or 1 without --mis, Part 4's paths otherwise; `direct`
/// is Part 3's direct-light integrator whatever else is asked (the grader's Part 3 renders use
/// it, so they run no Part 4 code), `path` Part 4's path integrator even at -m 0 or 1.
enum class IntegratorChoice { automatic, direct, path };

/// The settings of one render; the defaults are the course renderer's.
struct RenderSettings {
  int width = 480, height = 360;        ///< -r W H
  int samples_per_pixel = 1;            ///< -s
  int light_samples = 1;                ///< -l: samples per area light
  int max_depth = 1;                    ///< -m: 0 emitted only, 1 direct, 2 one bounce, ...
  int threads = 0;                      ///< -t: 0 means every core
  bool hemisphere_sampling = false;     ///< -H: uniform hemisphere instead of light sampling
  bool adaptive = false;                ///< -a given
  int adaptive_batch = 32;              ///< -a BATCH
  float adaptive_tolerance = 0.05f;     ///< -a TOL
  StoppingRule stopping_rule = kAssignmentStoppingRule;  ///< --stopping-rule (with -a)
  std::string environment_map;          ///< -e: image-based infinite light
  float lens_radius = 0.0f;             ///< -b: thin-lens aperture
  float focal_distance = -1.0f;         ///< -d: focal distance; negative keeps the scene's
  bool has_cell = false;                ///< -p given: render only a cell
  int cell_x = 0, cell_y = 0, cell_w = 0, cell_h = 0;  ///< -p X Y DX DY
  uint64_t seed = 0;                    ///< --seed: same seed, same image
  AccelKind accel = AccelKind::bvh_sah; ///< --bvh sah|median|none
  int bvh_leaf_size = 4;                ///< --leaf-size
  /// --bvh-width: 2 traverses Part 2's binary tree itself; kWideBvhWidth the wide tree
  /// collapsed from it (same answers, faster). The grader's Part 2 renders ask for 2.
  int bvh_width = kWideBvhWidth;
  ShadingMode shading = ShadingMode::light;
  IntegratorChoice integrator = IntegratorChoice::automatic;  ///< --integrator
  bool russian_roulette = true;         ///< --no-rr turns it off
  bool mis = false;                     ///< --mis: combine light and BSDF samples
  int only_bounce = -1;                 ///< --bounce K: only light that took exactly K bounces
};

}  // namespace pt
