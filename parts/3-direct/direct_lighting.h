// Part 3: light that reaches the camera straight from an emitter, or after one reflection.
// Step 2 (zero_bounce): zero_bounce_radiance; step 3 (hemisphere): estimate_direct_hemisphere;
// step 4 (importance): estimate_direct_importance; step 5 (one_bounce): one_bounce_radiance.
#pragma once

#include <glm/vec3.hpp>

#include "framework/geometry/surface_hit.h"
#include "framework/math/ray.h"
#include "framework/sampling/rng.h"
#include "framework/shading/lighting_context.h"
#include "framework/shading/shading_point.h"
#include "parts/3-direct/diffuse_bsdf.h"

namespace pt {

/// A surface point made ready for shading, its diffuse materials drawn by Part 3's DiffuseBsdf
/// (the framework's ShadingPointWith cannot name the student's type itself).
using ShadingPoint = ShadingPointWith<DiffuseBsdf>;

/// Step 2 (zero_bounce).
/// Light the surface hit by `ray` emits back along it (zero-bounce radiance): what its light in
/// ctx.lights sends back, so the camera sees the very emitter that light sampling samples.
glm::vec3 zero_bounce_radiance(const LightingContext& ctx, const Ray& ray, const SurfaceHit& hit);

/// Step 3 (hemisphere).
/// Direct light reflected at `sp` towards the viewer, estimated with ctx.light_samples uniform
/// directions of the hemisphere: what each direction's ray (spawn_ray from the hit) brings back,
/// ctx.lights.radiance_along (the lights as light sampling samples them, the environment where it
/// escapes), times f·cosθ, divided by the density 1/2π, averaged over the directions.
glm::vec3 estimate_direct_hemisphere(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng);

/// Step 4 (importance).
/// Direct light reflected at `sp`, estimated by sampling the lights: ctx.light_samples samples
/// of each area light (exactly one of a delta light, whatever -l says), each unblocked sample's
/// f·L·cosθ divided by its density and averaged per light. One shadow ray per sample, started
/// with spawn_shadow_ray (no epsilon of your own) and none for a sample whose f or L is zero.
glm::vec3 estimate_direct_importance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng);

/// Step 5 (one_bounce).
/// Direct light at `sp` by the estimator ctx asks for (hemisphere or light sampling); zero for
/// a specular surface, which no light sample can reach.
glm::vec3 one_bounce_radiance(const LightingContext& ctx, const ShadingPoint& sp, Rng& rng);

}  // namespace pt
