// Part 5: per-pixel adaptive sampling — stop taking samples once a pixel has converged.
#pragma once

#include "1-raygen/pixel_loop.h"
#include "render/pixel_stats.h"

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

/// The course's adaptive-sampling settings (-a BATCH TOL with -s as the maximum).
struct AdaptiveSettings {
  int max_samples = 64;    ///< -s: never more than this many samples
  int batch = 32;          ///< -a BATCH: convergence is checked after every batch
  float tolerance = 0.05f; ///< -a TOL: stop when the 95% confidence half-width ≤ TOL · mean
};

/// Photometric illuminance of a linear RGB radiance (Rec. 709 primaries).
inline double illuminance(const glm::vec3& rgb) {
  return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

/// Whether a pixel with these statistics has converged: I = 1.96·σ/√n ≤ tolerance·μ.
/// A pixel whose samples are all equal (σ = 0) has converged, even a black one.
bool pixel_converged(const IlluminanceStats& stats, float tolerance);

/// Estimates pixel `px` like estimate_pixel, but in batches of settings.batch samples (jittered),
/// stopping after the first batch that leaves the pixel converged, or at settings.max_samples.
/// Every sample's radiance goes into *stats. Returns the number of samples taken.
int estimate_pixel_adaptive(const Camera& camera, const PixelRef& px,
                            const AdaptiveSettings& settings, Rng& rng,
                            const RadianceFn& radiance, PixelStats* stats);

}  // namespace pt
