// Part 4: global illumination, light that reaches the camera after any number of bounces.
// Step 1 (path): estimate_global_illumination; steps 2 (bounces) and 3 (russian_roulette):
// at_least_one_bounce_radiance.
#pragma once

#include <glm/vec3.hpp>

#include "framework/math/ray.h"
#include "framework/sampling/rng.h"
#include "parts/3-direct/direct_lighting.h"

namespace pt {

/// Given, not a step.
/// Direct light at `sp` by the estimator ctx asks for: MIS with ctx.mis, else Part 3's
/// one_bounce_radiance.
glm::vec3 direct_radiance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng);

/// Steps 2 (bounces) and 3 (russian_roulette).
/// Light leaving `sp` towards the viewer after at least one bounce, where `sp` is the path's
/// vertex number `depth` (the camera ray's hit is 1): the direct light there (which took
/// `depth` bounces), plus, while depth < ctx.max_depth, what a BSDF-sampled ray brings back
/// from the next vertex (weighted by f·|cosθ|/pdf), with Russian roulette from the second bounce
/// on (a path that survives is divided by its chance to go on). After a specular vertex the next
/// surface's emission counts too, since no light sample could reach it; so a specular vertex at
/// depth = ctx.max_depth still follows its one direction, for that emission alone.
/// With ctx.only_bounce = K ≥ 0, only light that took exactly K bounces is kept.
glm::vec3 at_least_one_bounce_radiance(const LightingContext& ctx, const ShadingPoint& sp,
                                       int depth, Rng& rng);

/// Step 1 (path).
/// Radiance arriving along a camera ray: the emission it sees (or the environment), plus the
/// light reflected there after at least one bounce, up to ctx.max_depth bounces.
glm::vec3 estimate_global_illumination(const LightingContext& ctx, const Ray& ray, Rng& rng);

}  // namespace pt
