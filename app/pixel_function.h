// One pixel of a render: the camera's lens from the settings, and Part 1's pixel loop (or, with
// -a, Part 5's adaptive one) over the radiance function.
#pragma once

#include "framework/render/render_settings.h"
#include "framework/render/tile_renderer.h"
#include "framework/render/trace_context.h"
#include "framework/scene/camera.h"

namespace pt {

/// Applies -b and -d to the scene's camera.
void apply_lens(const RenderSettings& settings, Camera* camera);

/// One pixel by Part 1's loop (or Part 5's with -a), dropping non-finite samples to black and
/// counting them, so the summary can say so. `settings`, `camera` and `radiance` must outlive
/// the returned function.
PixelFn make_pixel_fn(const RenderSettings& settings, const Camera& camera,
                      const TracedRadianceFn& radiance);

}  // namespace pt
