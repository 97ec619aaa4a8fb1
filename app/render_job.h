// One render as the pathtracer command makes it (ray query given; radiance, pixel loop, tiles),
// shared by pathtracer and bench so that what bench times is what pathtracer renders.
#pragma once

#include "app/radiance.h"
#include "framework/geometry/ray_query.h"
#include "framework/render/film.h"
#include "framework/render/render_settings.h"
#include "framework/render/tile_renderer.h"
#include "framework/scene/scene.h"

namespace pt {

/// Renders `scene` (camera already placed) through `query` into *film, sized
/// settings.width × settings.height: make_radiance, make_pixel_fn and render_tiles in one call.
RenderReport render_scene(const RenderSettings& settings, const Scene& scene,
                          const RayQuery& query, Film* film,
                          const TileRenderOptions& options = {},
                          LightLayer layer = LightLayer::fast);

}  // namespace pt
