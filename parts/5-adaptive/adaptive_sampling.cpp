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
  // the half-width is that of the estimate you report: 1.96·σ/√n_E, with n_E = estimate_count
  // (the samples in the estimate, not the decision samples nor every sample). Converged when
  // it is at most tolerance·μ; with fewer than two decision samples, or no estimate sample, not
  // converged; with every decision sample equal (σ = 0), converged, even a black pixel.
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
  // STUDENT: sample one pixel until it has converged or has taken its maximum
  // (docs/handout/part5.md, step 2, has the idea).
  // In: settings (batch, tolerance, max_samples, the stopping rule), next_sample (the radiance of
  // the pixel's next sample), converged (the rule you are handed: the renderer hands you your
  // pixel_converged). Out: *estimate holds the samples that make the pixel's value; the return
  // value is how many samples were taken.
  // What must hold, and is graded:
  // - sample number i (from 0) feeds the decision statistics when sample_decides(settings.rule,
  //   i) and *estimate when sample_counts(settings.rule, i) (under the split rule, never both);
  // - convergence is asked after each whole batch of settings.batch samples, with the estimate's
  //   count, and the loop stops after the first batch after which it holds;
  // - never more than settings.max_samples samples; the count returned includes the decision
  //   samples (the sample-rate image shows it).
  PT_STUDENT_TODO("part 5", "sample_pixel_adaptive");
  (void)settings, (void)next_sample, (void)converged;
  estimate->add(glm::vec3(0.0f));
  return 1;
}

}  // namespace pt
