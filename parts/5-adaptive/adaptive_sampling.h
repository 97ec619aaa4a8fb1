// Part 5: per-pixel adaptive sampling — stop taking samples once a pixel has converged.
// Step 1 (convergence): pixel_converged; step 2 (adaptive_loop): sample_pixel_adaptive.
#pragma once

#include <functional>

#include <glm/vec3.hpp>

#include "framework/render/pixel_stats.h"

namespace pt {

/// Running mean and variance of a pixel's sample illuminances. Welford's update in double: the
/// course's Σx and Σx² in float lose every significant digit of the variance for a bright pixel
/// whose samples barely differ (Σx² and (Σx)²/n agree in all the digits a float keeps), and
/// then a noisy pixel looks converged or a converged one never stops.
struct IlluminanceStats {
  long count = 0;
  double mean = 0.0;
  double m2 = 0.0;  ///< sum of squared deviations from the mean

  void add(double x) {
    ++count;
    double delta = x - mean;
    mean += delta / double(count);
    m2 += delta * (x - mean);
  }
  /// Unbiased sample variance (0 with fewer than two samples).
  double variance() const { return count > 1 ? m2 / double(count - 1) : 0.0; }
};

/// One sample in kDecisionStride of a pixel decides when to stop and never enters the pixel's
/// value; the others form the value and never take part in the decision. The course's rule
/// decides on the very samples it averages, so a heavy-tailed pixel whose batch happened to miss
/// its rare bright samples looks converged and stops too dark: a quarter of the samples is the
/// price of an answer that is unbiased whatever the pixel's distribution.
constexpr int kDecisionStride = 4;

/// Whether the pixel's `index`-th sample (from 0) is a decision sample: the last of each stride.
inline bool is_decision_sample(long index) {
  return index % kDecisionStride == kDecisionStride - 1;
}

/// The course's adaptive-sampling settings (-a BATCH TOL with -s as the maximum).
struct AdaptiveSettings {
  int max_samples = 64;    ///< -s: never more than this many samples, decision samples included
  int batch = 32;          ///< -a BATCH: convergence is checked after every batch
  float tolerance = 0.05f; ///< -a TOL: stop when the 95% confidence half-width ≤ TOL · mean
};

/// Photometric illuminance of a linear RGB radiance (Rec. 709 primaries).
inline double illuminance(const glm::vec3& rgb) {
  return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

/// The radiance of one more sample of the pixel being estimated, through a new uniformly jittered
/// point of it: each call takes a new sample (the renderer makes it from Part 1's camera ray).
using PixelSampleFn = std::function<glm::vec3()>;

/// Whether a pixel has converged: the 95% confidence half-width of the estimate the pixel
/// reports, I = 1.96·σ/√n_E, is at most tolerance·μ, where σ and μ come from the decision
/// samples' illuminances (`decision`) and n_E = `estimate_count` is the number of samples in
/// the estimate. Fewer than two decision samples say nothing about σ: not converged. A pixel
/// whose decision samples are all equal (σ = 0) has converged, even a black one.
bool pixel_converged(const IlluminanceStats& decision, long estimate_count, float tolerance);

/// Samples a pixel in batches of settings.batch samples (each the radiance next_sample()
/// returns), stopping after the first batch that leaves the pixel converged, or at
/// settings.max_samples. Sample i goes into the decision statistics if is_decision_sample(i),
/// else (its radiance) into *estimate, the pixel's value. Returns the number of samples taken,
/// decision samples included.
int sample_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                          PixelStats* estimate);

}  // namespace pt
