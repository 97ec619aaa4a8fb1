// A pixel's samples as the adaptive sampler decides by them: their photometric illuminance, and
// its running mean and variance, computed without cancellation.
#pragma once

#include <glm/vec3.hpp>

namespace pt {

/// Photometric illuminance of a linear RGB radiance (Rec. 709 primaries).
inline double illuminance(const glm::vec3& rgb) {
  return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

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

}  // namespace pt
