// Part 4, step 4 (mis), beyond the course: direct light by multiple importance sampling of lights
// and of the BSDF (power_heuristic, estimate_direct_mis).
#pragma once

#include <glm/vec3.hpp>

#include "framework/sampling/rng.h"
#include "parts/3-direct/direct_lighting.h"

namespace pt {

/// Step 4 (mis).
/// Power heuristic (Veach 1997, β = 2) for a sample of a strategy taken n_a times with density
/// pdf_a, against one taken n_b times with density pdf_b.
float power_heuristic(int n_a, float pdf_a, int n_b, float pdf_b);

/// Step 4 (mis).
/// Direct light at `sp` from ctx.light_samples light samples per light (one per delta light)
/// and ctx.light_samples BSDF samples, each weighted by the power heuristic, so that whichever
/// strategy suits the light (a big dim light for the BSDF, a small bright one for the light)
/// dominates. A BSDF sample counts when its ray reaches a light the LightSet can also sample
/// (an emitter, an area light's rectangle as its light samples are drawn, or the environment),
/// with the radiance and density the LightSet gives for the very point it reached. A light no ray
/// can hit (can_be_hit() false: a point, spot or directional light, or an area light without a
/// panel) keeps weight 1 for its samples.
glm::vec3 estimate_direct_mis(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng);

}  // namespace pt
