#include "parts/5-adaptive/adaptive_sampling.h"

#include <cmath>

#include "parts/1-raygen/camera_ray.h"
#include "framework/student/todo.h"

namespace pt {

Ray jittered_pixel_ray(const Camera& camera, const PixelRef& px, Rng& rng) {
  const float aspect = float(px.width) / float(px.height);
  const glm::vec2 jitter = rng.next_2d();
  // Rows count down from the top, the film up from the bottom.
  const glm::vec2 film((float(px.x) + jitter.x) / float(px.width),
                       1.0f - (float(px.y) + jitter.y) / float(px.height));
  const glm::vec2 lens = (camera.lens_radius > 0.0f) ? rng.next_2d() : glm::vec2(0.5f);
  return generate_camera_ray(camera, aspect, film, lens);
}

bool pixel_converged(const IlluminanceStats& decision, long estimate_count, float tolerance) {
  // BEGIN SOLUTION
  if (decision.count < 2 || estimate_count < 1) return false;
  double half_width = 1.96 * std::sqrt(decision.variance() / double(estimate_count));
  return half_width <= double(tolerance) * decision.mean;
  // END SOLUTION
  // STUDENT: σ and μ come from the decision samples (decision.variance(), decision.mean), but
  // the half-width is that of the estimate you report: 1.96·σ/√estimate_count. Converged when
  // it is at most tolerance·μ; with fewer than two decision samples, not converged.
  PT_STUDENT_TODO("part 5", "pixel_converged");
  (void)decision, (void)estimate_count, (void)tolerance;
  return false;
}

// The pixel's value is the mean of the estimate samples up to a stopping time that depends only
// on the decision samples, which are independent of them: conditioned on when it stops, that
// mean is still a mean of independent samples, so its expectation is the pixel's true value.
int sample_pixel_adaptive(const Camera& camera, const PixelRef& px,
                          const AdaptiveSettings& settings, Rng& rng, const RadianceFn& radiance,
                          PixelStats* estimate) {
  // BEGIN SOLUTION
  const int batch = settings.batch < 1 ? 1 : settings.batch;
  IlluminanceStats decision;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec3 L = radiance(jittered_pixel_ray(camera, px, rng), rng);
      if (is_decision_sample(taken))
        decision.add(illuminance(L));
      else
        estimate->add(L);
    }
    if (pixel_converged(decision, estimate->count, settings.tolerance)) break;
  }
  return taken;
  // END SOLUTION
  // STUDENT: take samples in batches of settings.batch, each the radiance along
  // jittered_pixel_ray. Sample number `taken` (from 0) goes only into an IlluminanceStats of
  // decision samples when is_decision_sample(taken), otherwise only into *estimate. After each
  // batch stop if pixel_converged(decision, estimate->count, ...) says so. Never take more than
  // settings.max_samples. Return how many samples you took, decision samples included.
  PT_STUDENT_TODO("part 5", "sample_pixel_adaptive");
  (void)camera, (void)px, (void)settings, (void)rng, (void)radiance;
  estimate->add(glm::vec3(0.0f));
  return 1;
}

int estimate_pixel_adaptive(const Camera& camera, const PixelRef& px,
                            const AdaptiveSettings& settings, Rng& rng,
                            const RadianceFn& radiance, PixelStats* stats) {
  const long before = stats->count;
  const int taken = sample_pixel_adaptive(camera, px, settings, rng, radiance, stats);
  const long kept_out = long(taken) - (stats->count - before);
  if (kept_out > 0) stats->decision_samples += kept_out;
  return taken;
}

}  // namespace pt
