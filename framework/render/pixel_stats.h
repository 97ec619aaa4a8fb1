// The running statistics of one pixel's samples: mean and variance, without cancellation.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

namespace pt {

/// Mean and sum of squared deviations of a pixel's samples, updated one sample at a time with
/// Welford's method in double precision: the naive Σx² − (Σx)²/n cancels catastrophically for a
/// bright pixel with little noise, this does not. The variance feeds the statistical comparison
/// of renders; adaptive sampling (Part 5) keeps its own illuminance statistics the same way.
///
/// 56 bytes, the film's whole cost per pixel: the counts are 32-bit, since a pixel takes at most
/// -s samples (an int), and sit together so that no padding follows them.
struct PixelStats {
  int32_t count = 0;
  /// Samples traced for the pixel but kept out of its estimate: adaptive sampling's decision
  /// samples (Part 5), spent apart so that when to stop does not bias the value. The sample-rate
  /// image and the render's sample total count them; `count`, which weighs the variance in the
  /// statistical comparison of renders, does not.
  int32_t decision_samples = 0;
  glm::dvec3 mean{0.0};
  glm::dvec3 m2{0.0};

  void add(const glm::vec3& sample) {
    ++count;
    glm::dvec3 x(sample);
    glm::dvec3 delta = x - mean;
    mean += delta / double(count);
    m2 += delta * (x - mean);
  }
  /// Every sample traced for the pixel, the estimate's and the decision's.
  long samples_taken() const { return long(count) + long(decision_samples); }
  /// Unbiased sample variance of one sample (0 with fewer than two samples).
  glm::dvec3 variance() const { return count > 1 ? m2 / double(count - 1) : glm::dvec3(0.0); }
};

static_assert(sizeof(PixelStats) == 56, "the film's bytes per pixel are stated in film.h");

}  // namespace pt
