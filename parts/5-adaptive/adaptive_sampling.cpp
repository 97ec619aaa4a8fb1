// Part 5, step 1 (convergence): pixel_converged; step 2 (adaptive_loop): sample_pixel_adaptive.
#include "parts/5-adaptive/adaptive_sampling.h"

#include <cmath>

#include "framework/student/todo.h"

namespace pt {

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

// Under the split rule the pixel's value is the mean of the estimate samples up to a stopping time
// that depends only on the decision samples, which are independent of them: conditioned on when
// it stops, that mean is still a mean of independent samples, so its expectation is the pixel's
// true value. Under the course's rule the same loop decides on the samples it averages.
int sample_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                          PixelStats* estimate, const ConvergenceRule& converged) {
  // BEGIN SOLUTION
  const int batch = settings.batch < 1 ? 1 : settings.batch;
  IlluminanceStats decision;
  int taken = 0;
  while (taken < settings.max_samples) {
    for (int i = 0; i < batch && taken < settings.max_samples; ++i, ++taken) {
      glm::vec3 L = next_sample();
      if (sample_decides(settings.rule, taken)) decision.add(illuminance(L));
      if (sample_counts(settings.rule, taken)) estimate->add(L);
    }
    if (converged(decision, estimate->count, settings.tolerance)) break;
  }
  return taken;
  // END SOLUTION
  // STUDENT: take samples in batches of settings.batch, each the radiance next_sample()
  // returns. Sample number `taken` (from 0) goes into an IlluminanceStats of decision samples
  // when sample_decides(settings.rule, taken), and into *estimate when
  // sample_counts(settings.rule, taken). After each batch stop if converged(decision,
  // estimate->count, settings.tolerance) says so (the rule you are handed: the renderer hands
  // you your pixel_converged). Never take more than settings.max_samples. Return how many
  // samples you took, decision samples included.
  PT_STUDENT_TODO("part 5", "sample_pixel_adaptive");
  (void)settings, (void)next_sample, (void)converged;
  estimate->add(glm::vec3(0.0f));
  return 1;
}

}  // namespace pt
