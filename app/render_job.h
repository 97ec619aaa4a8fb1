// One render as the pathtracer command makes it (ray query, radiance, pixel loop, tiles), shared
// by pathtracer and bench so that what bench times is what pathtracer renders.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/geometry/ray_query.h"
#include "framework/render/film.h"
#include "framework/render/render_settings.h"
#include "framework/render/tile_renderer.h"
#include "framework/render/trace_context.h"
#include "framework/scene/camera.h"
#include "framework/scene/material.h"
#include "framework/scene/scene.h"

namespace pt {

/// The structure that answers the rays: Part 2's BVH (SAH or midpoint splits), or brute force.
std::unique_ptr<RayQuery> make_ray_query(const RenderSettings& settings, const Scene& scene);

/// The BVH's build statistics, one line, for --info.
std::string describe_bvh(const RenderSettings& settings, const Scene& scene);

/// The material kinds the lighting parts draw as the file asks.
std::vector<MaterialKind> rendered_material_kinds(const RenderSettings& settings);

/// What a camera ray brings back: the normals view (--normals, or a scene with nothing that
/// emits), or the light Parts 3 and 4 estimate. The integrator lives as long as the function.
/// Every ray traced for a sample (camera, shadow, bounce) is added to the tile's context.
/// Throws std::runtime_error naming the file when the environment map cannot be read.
TracedRadianceFn make_radiance(const RenderSettings& settings, const Scene& scene,
                               const RayQuery& query);

/// Applies -b and -d to the scene's camera.
void apply_lens(const RenderSettings& settings, Camera* camera);

/// One pixel by Part 1's loop (or Part 5's with -a), dropping non-finite samples to black and
/// counting them, so the summary can say so. `settings`, `camera` and `radiance` must outlive
/// the returned function.
PixelFn make_pixel_fn(const RenderSettings& settings, const Camera& camera,
                      const TracedRadianceFn& radiance);

/// Renders `scene` (camera already placed) through `query` into *film, sized
/// settings.width × settings.height: make_radiance, make_pixel_fn and render_tiles in one call.
RenderReport render_scene(const RenderSettings& settings, const Scene& scene,
                          const RayQuery& query, Film* film,
                          const TileRenderOptions& options = {});

}  // namespace pt
