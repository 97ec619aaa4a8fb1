// Not needed for the assignment: the definitions of framework/render/tile_renderer.h.
#include "framework/render/tile_renderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "framework/render/progress.h"

namespace pt {

PixelRect render_region(const RenderSettings& settings) {
  if (settings.has_cell)
    return {settings.cell_x, settings.cell_y, settings.cell_x + settings.cell_w,
            settings.cell_y + settings.cell_h};
  return {0, 0, settings.width, settings.height};
}

namespace {

// The arena a render runs in: settings.threads threads, or every core for 0. start_render_threads
// starts the same one that render_tiles then uses.
tbb::task_arena render_arena(const RenderSettings& settings) {
  return tbb::task_arena(settings.threads == 0 ? tbb::task_arena::automatic : settings.threads);
}

}  // namespace

RenderReport render_tiles(const RenderSettings& settings, const PixelFn& pixel, Film* film,
                          const TileRenderOptions& options) {
  if (film->width() != settings.width || film->height() != settings.height)
    throw std::invalid_argument("render_tiles: the film is not the size of the image");
  const PixelRect region = render_region(settings);
  if (region.x0 < 0 || region.y0 < 0 || region.x1 > settings.width ||
      region.y1 > settings.height || region.width() < 1 || region.height() < 1)
    throw std::invalid_argument("render_tiles: the cell is not inside the image");
  if (settings.threads < 0) throw std::invalid_argument("render_tiles: negative thread count");

  const std::vector<PixelRect> tiles = split_into_tiles(region, options.tile_size);
  std::vector<TraceContext> contexts(tiles.size());
  ProgressBar progress(region.area(), options.progress);
  const int width = settings.width;
  const uint64_t seed = settings.seed;

  tbb::task_arena arena = render_arena(settings);
  RenderReport report;
  report.threads = arena.max_concurrency();
  auto start = std::chrono::steady_clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t t = range.begin(); t != range.end(); ++t) {
                          const PixelRect& tile = tiles[t];
                          TraceContext& context = contexts[t];
                          for (int y = tile.y0; y < tile.y1; ++y)
                            for (int x = tile.x0; x < tile.x1; ++x) {
                              Rng rng(seed, uint64_t(y) * uint64_t(width) + uint64_t(x));
                              pixel(x, y, rng, context, &film->at(x, y));
                            }
                          progress.advance(tile.area());
                        }
                      });
  });
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();

  report.width = settings.width;
  report.height = settings.height;
  report.region = region;
  for (const TraceContext& c : contexts) {
    report.rays += c.rays.rays;
    report.camera_rays += c.rays.camera;
    report.shadow_rays += c.rays.shadow;
    report.packets += c.rays.packets;
    report.packet_rays += c.rays.packet_rays;
    report.nonfinite_samples += c.nonfinite_samples;
  }
  for (int y = region.y0; y < region.y1; ++y)
    for (int x = region.x0; x < region.x1; ++x) report.samples += film->at(x, y).samples_taken();
  return report;
}

void start_render_threads(const RenderSettings& settings) {
  tbb::task_arena arena = render_arena(settings);
  arena.execute([&] { tbb::parallel_for(0, arena.max_concurrency(), [](int) {}); });
}

std::string summary_line(const RenderReport& report) {
  char buffer[512];
  std::string text = "render: " + std::to_string(report.width) + "x" + std::to_string(report.height);
  const PixelRect& r = report.region;
  if (r.x0 != 0 || r.y0 != 0 || r.width() != report.width || r.height() != report.height)
    text += " (cell " + std::to_string(r.x0) + " " + std::to_string(r.y0) + " " +
            std::to_string(r.width()) + " " + std::to_string(r.height()) + ")";
  double spp = r.area() > 0 ? double(report.samples) / double(r.area()) : 0.0;
  if (spp == std::floor(spp))
    std::snprintf(buffer, sizeof buffer, ", %.0f spp", spp);
  else
    std::snprintf(buffer, sizeof buffer, ", %.1f spp on average", spp);
  text += buffer;
  double rate = report.seconds > 0.0 ? double(report.rays) / report.seconds / 1e6 : 0.0;
  std::snprintf(buffer, sizeof buffer, ", %.2f s, %.1f M rays/s, %d thread%s", report.seconds, rate,
                report.threads, report.threads == 1 ? "" : "s");
  text += buffer;
  if (report.nonfinite_samples > 0)
    text += "; warning: " + std::to_string(report.nonfinite_samples) +
            " samples were NaN or infinite and counted as black";
  return text;
}

}  // namespace pt
