// Not needed for the assignment: the definitions of framework/stats/allocation_bound.h.
#include "framework/stats/allocation_bound.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace pt {

AllocationBound relmse_allocation_bound(const RenderEstimate& estimate, const Image& reference,
                                        const std::vector<double>& sample_cost, double epsilon) {
  const size_t pixels = size_t(estimate.width) * size_t(estimate.height);
  if (estimate.width != reference.width() || estimate.height != reference.height() ||
      pixels == 0 || estimate.variance.size() != pixels ||
      (!sample_cost.empty() && sample_cost.size() != pixels))
    throw std::invalid_argument(
        "allocation bound: the estimate is " + std::to_string(estimate.width) + "x" +
        std::to_string(estimate.height) + " and the reference " + std::to_string(reference.width()) +
        "x" + std::to_string(reference.height()) + " with " + std::to_string(sample_cost.size()) +
        " costs; they must be the same, non-empty size (and the costs one a pixel, or none)");
  double sum_a = 0.0, sum_root = 0.0, sum_cost = 0.0, sum_root_ac = 0.0;
  size_t zero = 0;
  for (int y = 0; y < estimate.height; ++y)
    for (int x = 0; x < estimate.width; ++x) {
      const size_t i = size_t(y) * size_t(estimate.width) + size_t(x);
      const glm::vec3& var = estimate.variance[i];
      const glm::vec3& ref = reference.at(x, y);
      double a = 0.0;
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(var[c]) || !std::isfinite(ref[c]) || var[c] < 0.0f)
          throw std::invalid_argument("allocation bound: pixel (" + std::to_string(x) + ", " +
                                      std::to_string(y) + ") channel " + std::to_string(c) +
                                      " has variance " + std::to_string(var[c]) +
                                      " and reference " + std::to_string(ref[c]) +
                                      "; both must be finite and the variance not negative");
        a += double(var[c]) / (double(ref[c]) * double(ref[c]) + epsilon);
      }
      a /= 3.0;
      sum_a += a;
      sum_root += std::sqrt(a);
      zero += a == 0.0;
      if (!sample_cost.empty()) {
        const double c = sample_cost[i];
        if (!(c > 0.0) || !std::isfinite(c))
          throw std::invalid_argument("allocation bound: pixel (" + std::to_string(x) + ", " +
                                      std::to_string(y) + ") has a cost per sample of " +
                                      std::to_string(c) + "; it must be positive and finite");
        sum_cost += c;
        sum_root_ac += std::sqrt(a * c);
      }
    }
  AllocationBound bound;
  bound.zero_variance_share = double(zero) / double(pixels);
  bound.best_time_fraction =
      sample_cost.empty() ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  if (sum_a > 0.0) {
    bound.best_sample_fraction = sum_root * sum_root / (double(pixels) * sum_a);
    if (!sample_cost.empty()) bound.best_time_fraction = sum_root_ac * sum_root_ac / (sum_a * sum_cost);
  }
  return bound;
}

}  // namespace pt
