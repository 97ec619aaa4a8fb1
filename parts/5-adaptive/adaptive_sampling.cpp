#include "5-adaptive/adaptive_sampling.h"

#include <cmath>

#include "1-raygen/camera_ray.h"
#include "student/todo.h"

namespace pt {

bool pixel_converged(const IlluminanceStats& stats, float tolerance) {
  // BEGIN SOLUTION
  if (stats.count < 2) return false;
  double half_width = 1.96 * std::sqrt(stats.variance() / double(stats.count));
  return half_width <= double(tolerance) * stats.mean;
  // END SOLUTION
  // STUDENT: compute the 95% confidence half-width 1.96·σ/√n from stats.variance() and
  // stats.count, and compare it with tolerance·μ (μ = stats.mean).
  PT_STUDENT_TODO("part 5", "pixel_converged");
  (void)stats, (void)tolerance;
  return false;
}

int estimate_pixel_adaptive(const Camera& camera, const PixelRef& px,
                            const AdaptiveSettings& settings, Rng& rng,
                            const RadianceFn& radiance, PixelStats* stats) {
  // BEGIN SOLUTION
  const float aspect = float(px.width) / float(px.height);
  const int batch = settings.batch < 1 ? 1 : settings.batch;
  IlluminanceStats lum;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec2 jitter = rng.next_2d();
      glm::vec2 film((float(px.x) + jitter.x) / float(px.width),
                     1.0f - (float(px.y) + jitter.y) / float(px.height));
      glm::vec3 L = radiance(generate_camera_ray(camera, aspect, film, rng.next_2d()), rng);
      stats->add(L);
      lum.add(illuminance(L));
    }
    if (pixel_converged(lum, settings.tolerance)) break;
  }
  return taken;
  // END SOLUTION
  // STUDENT: take samples as estimate_pixel does, batch by batch; keep the illuminance of each
  // sample in an IlluminanceStats; after each batch stop if pixel_converged says so. Never take
  // more than settings.max_samples. Return how many samples you took.
  PT_STUDENT_TODO("part 5", "estimate_pixel_adaptive");
  (void)camera, (void)px, (void)settings, (void)rng, (void)radiance;
  stats->add(glm::vec3(0.0f));
  return 1;
}

}  // namespace pt
