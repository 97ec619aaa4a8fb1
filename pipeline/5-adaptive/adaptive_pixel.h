// Given code on Part 5: one pixel estimated adaptively, its samples made from Part 1's camera rays
// and the decision samples recorded, so the sample-rate image shows every sample taken.
#pragma once

#include "framework/render/pixel_stats.h"
#include "framework/sampling/rng.h"
#include "framework/scene/camera.h"
#include "parts/1-raygen/pixel_loop.h"
#include "parts/5-adaptive/adaptive_sampling.h"

namespace pt {

/// Estimates a pixel adaptively (sample_pixel_adaptive) from the samples `next_sample` returns,
/// and records on *stats the samples that went into the decision only, so the sample-rate image
/// shows every sample taken while the estimate's count stays that of the samples it averages.
/// Returns the samples taken.
int estimate_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                            PixelStats* stats);

/// The same with the stopping rule `converged` in place of pixel_converged (step 2's tests).
int estimate_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                            PixelStats* stats, const ConvergenceRule& converged);

/// Estimates pixel `px` like estimate_pixel, but adaptively: each sample is the radiance along
/// camera_ray_through_pixel at a uniformly jittered offset (then a lens sample, for a thin
/// lens), drawn from `rng`, as the pixel loop draws them.
int estimate_pixel_adaptive(const Camera& camera, const PixelRef& px,
                            const AdaptiveSettings& settings, Rng& rng,
                            const RadianceFn& radiance, PixelStats* stats);

}  // namespace pt
