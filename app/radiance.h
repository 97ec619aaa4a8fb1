// What a camera ray brings back in a render: the normals view or the light the integrator
// estimates, every ray it traces counted.
#pragma once

#include <string>
#include <vector>

#include "framework/geometry/ray_query.h"
#include "framework/render/render_settings.h"
#include "framework/render/tile_renderer.h"
#include "framework/render/trace_context.h"
#include "framework/scene/material.h"
#include "framework/scene/scene.h"

namespace pt {

/// The material kinds the lighting parts draw as the file asks.
std::vector<MaterialKind> rendered_material_kinds(const RenderSettings& settings);

/// Which code answers the framework's light samples and shadow rays: the solution-only fast
/// layer where this build has it (app/fast), or the framework's own definitions. Both give the
/// same bits; `bench layers` renders with each to hold the whole renderer to that.
enum class LightLayer { fast, plain };

/// What a camera ray brings back: the normals view (--normals, or a scene with nothing that
/// emits), or the light Parts 3 and 4 estimate (pipeline/4-global's Integrator). The integrator
/// lives as long as the function; `scene` and `query` must outlive it. Every ray traced for a
/// sample (camera, shadow, bounce) is added to the tile's context. Throws std::runtime_error naming the file when the environment map
/// cannot be read.
TracedRadianceFn make_radiance(const RenderSettings& settings, const Scene& scene,
                               const RayQuery& query, LightLayer layer = LightLayer::fast);

/// The render's rays by kind, per second of its tile loop, and how its shadow rays went in
/// packets: "rays: camera 0.8, shadow 21.9, bounce and other 1.5 M/s; shadow packets: 96 % of
/// the shadow rays, 7.8 rays a packet" (bounce and other: the nearest-hit queries past the
/// camera's, the panel checks of shadow rays among them).
std::string ray_kinds_line(const RenderReport& report);

/// The warning a render owes when it will show normals instead of light because nothing in the
/// scene emits (no usable light, no emissive surface, no -e map); empty otherwise.
std::string no_light_warning(const RenderSettings& settings, const Scene& scene);

}  // namespace pt
