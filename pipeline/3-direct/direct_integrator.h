// Given code on Part 3: the radiance of a camera ray by direct light alone (zero and one bounce),
// so that Part 3's renders (-m 0 and -m 1) need no Part 4 code.
#pragma once

#include <glm/vec3.hpp>

#include "framework/math/ray.h"
#include "framework/sampling/rng.h"
#include "framework/shading/lighting_context.h"

namespace pt {

/// Radiance arriving along camera ray `ray` for ctx.max_depth <= 1: the emission it sees (or the
/// environment), plus, with ctx.max_depth == 1, one_bounce_radiance at its hit; at a specular hit
/// (which no light sample can reach) the emission its one reflected or refracted ray sees
/// instead. ctx.only_bounce = 0 or 1 keeps that bounce only. The same estimate, drawing the same
/// random numbers, as Part 4's estimate_global_illumination at these depths without MIS.
glm::vec3 estimate_direct_illumination(const LightingContext& ctx, const Ray& ray, Rng& rng);

}  // namespace pt
