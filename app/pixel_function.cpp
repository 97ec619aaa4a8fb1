#include "app/pixel_function.h"

#include <cmath>

#include "parts/1-raygen/pixel_loop.h"
#include "pipeline/5-adaptive/adaptive_pixel.h"

namespace pt {

void apply_lens(const RenderSettings& settings, Camera* camera) {
  camera->lens_radius = settings.lens_radius;
  if (settings.focal_distance > 0.0f) camera->focal_distance = settings.focal_distance;
}

PixelFn make_pixel_fn(const RenderSettings& settings, const Camera& camera,
                      const TracedRadianceFn& radiance) {
  AdaptiveSettings adaptive;
  adaptive.max_samples = settings.samples_per_pixel;
  adaptive.batch = settings.adaptive_batch;
  adaptive.tolerance = settings.adaptive_tolerance;
  adaptive.rule = settings.stopping_rule;
  return [&settings, &camera, &radiance, adaptive](int x, int y, Rng& rng, TraceContext& context,
                                                   PixelStats* stats) {
    RadianceFn sample = [&radiance, &context](const Ray& ray, Rng& r) {
      glm::vec3 L = radiance(ray, r, context);
      if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
        ++context.nonfinite_samples;
        return glm::vec3(0.0f);
      }
      return L;
    };
    PixelRef px{x, y, settings.width, settings.height};
    if (settings.adaptive)
      estimate_pixel_adaptive(camera, px, adaptive, rng, sample, stats);
    else
      estimate_pixel(camera, px, settings.samples_per_pixel, rng, sample, stats);
  };
}

}  // namespace pt
