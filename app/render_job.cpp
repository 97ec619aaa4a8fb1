#include "app/render_job.h"

#include "app/pixel_function.h"
#include "app/radiance.h"

namespace pt {

RenderReport render_scene(const RenderSettings& settings, const Scene& scene,
                          const RayQuery& query, Film* film, const TileRenderOptions& options,
                          LightLayer layer) {
  const TracedRadianceFn radiance = make_radiance(settings, scene, query, layer);
  return render_tiles(settings, make_pixel_fn(settings, scene.camera, radiance), film, options);
}

}  // namespace pt
