// Not needed for the assignment: the definitions of pipeline/5-adaptive/adaptive_pixel.h.
#include "pipeline/5-adaptive/adaptive_pixel.h"

namespace pt {

int estimate_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                            PixelStats* stats) {
  return estimate_pixel_adaptive(settings, next_sample, stats, pixel_converged);
}

int estimate_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                            PixelStats* stats, const ConvergenceRule& converged) {
  const long before = stats->count;
  const int taken = sample_pixel_adaptive(settings, next_sample, stats, converged);
  const long kept_out = long(taken) - (stats->count - before);
  if (kept_out > 0) stats->decision_samples += kept_out;
  return taken;
}

int estimate_pixel_adaptive(const Camera& camera, const PixelRef& px,
                            const AdaptiveSettings& settings, Rng& rng,
                            const RadianceFn& radiance, PixelStats* stats) {
  const PixelSampleFn next_sample = [&]() {
    const glm::vec2 offset = rng.next_2d();
    const glm::vec2 lens = (camera.lens_radius > 0.0f) ? rng.next_2d() : glm::vec2(0.5f);
    return radiance(camera_ray_through_pixel(camera, px, offset, lens), rng);
  };
  return estimate_pixel_adaptive(settings, next_sample, stats);
}

}  // namespace pt
