// Not needed for the assignment.
// Renders an image tile by tile on every core, identically whatever the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "framework/render/film.h"
#include "framework/render/pixel_stats.h"
#include "framework/render/render_settings.h"
#include "framework/render/tiles.h"
#include "framework/render/trace_context.h"
#include "framework/sampling/rng.h"

namespace pt {

/// Renders pixel (x, y): adds its samples to *stats, drawing random numbers from `rng` only and
/// reporting rays to `context`. The renderer hands every pixel its own Rng(seed, y·width + x),
/// so a pixel's value depends on the seed and its position, not on the thread or the schedule.
using PixelFn =
    std::function<void(int x, int y, Rng& rng, TraceContext& context, PixelStats* stats)>;

/// How the tiles are cut and whether a progress bar is drawn.
struct TileRenderOptions {
  int tile_size = 32;
  bool progress = false;  ///< draw the bar (pass ProgressBar::stderr_is_terminal())
};

/// What a render did, for its summary line and for bench.
struct RenderReport {
  int width = 0, height = 0;
  PixelRect region;           ///< the pixels rendered (the whole image, or the -p cell)
  int threads = 0;            ///< threads the arena had
  double seconds = 0.0;       ///< wall time of the tile loop
  uint64_t rays = 0;          ///< rays the radiance function reported
  /// Of those, camera and shadow rays, and the packets the shadow rays were traced in (RayCounter).
  uint64_t camera_rays = 0, shadow_rays = 0, packets = 0, packet_rays = 0;
  long samples = 0;           ///< samples taken (counted on the film)
  uint64_t nonfinite_samples = 0;
};

/// The pixels a render covers: the -p cell when there is one, else the whole image.
PixelRect render_region(const RenderSettings& settings);

/// Renders render_region(settings) into *film (sized settings.width × settings.height) in
/// tiles, in parallel on settings.threads threads (0: every core) of a oneTBB task arena of its
/// own. Rays and non-finite samples are counted per tile and summed at the end.
RenderReport render_tiles(const RenderSettings& settings, const PixelFn& pixel, Film* film,
                          const TileRenderOptions& options = {});

/// Starts oneTBB, as render_tiles will use it, before anything else loads shared objects. The
/// first parallel loop of a process opens oneTBB's allocator and thread-manager libraries, and a
/// library opened while another thread opens its own waits for it (the dynamic loader has one
/// lock): a render started beside the image module's preload (a few hundred shared objects)
/// sat idle until the preload was done. Call this first, and the render starts at once.
void start_render_threads(const RenderSettings& settings);

/// "render: 480x360, 16 spp, 2.31 s, 12.3 M rays/s" (plus the cell, the thread count, and a
/// warning when samples were not finite).
std::string summary_line(const RenderReport& report);

}  // namespace pt
