// Not needed for the assignment.
// What one tile's radiance calls share: counters kept per tile, so the hot loop needs no atomics.
#pragma once

#include <cstdint>
#include <functional>

#include <glm/vec3.hpp>

#include "framework/math/ray.h"
#include "framework/sampling/rng.h"

namespace pt {

/// Rays traced by one tile. Plain counters: each tile has its own and the renderer sums them
/// when every tile is done, so counting costs an add, not a shared cache line.
struct RayCounter {
  uint64_t rays = 0;
  /// Of those, by kind: camera rays (one a camera sample) and shadow rays (occlusion queries);
  /// the rest are nearest-hit queries past the camera's (bounces, and the panel checks of
  /// shadow rays that meet a light's own panel). Zero where the radiance function does not
  /// tell kinds apart.
  uint64_t camera = 0, shadow = 0;
  /// Shadow rays traced together: how many packets, and how many rays in all.
  uint64_t packets = 0, packet_rays = 0;
  void add(uint64_t n = 1) { rays += n; }
};

/// Per-tile state a radiance function may use: where it reports the rays it traced and the
/// samples it could not make finite (a NaN or infinite sample is counted and dropped to black
/// by the caller, and the render's summary says so, rather than poisoning a pixel silently).
struct TraceContext {
  RayCounter rays;
  uint64_t nonfinite_samples = 0;
};

/// Radiance arriving along a camera ray, reporting its work to the tile's context.
using TracedRadianceFn = std::function<glm::vec3(const Ray& ray, Rng& rng, TraceContext& context)>;

}  // namespace pt
