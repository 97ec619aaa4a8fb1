// Not needed for the assignment: the definitions of framework/stats/time_to_error.h.
#include "framework/stats/time_to_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pt {
namespace {

/// The time on the log-log line through a and b where the error is `target`; NaN when the line
/// does not slope down (then no time along it reaches the target from above).
double along(const ErrorPoint& a, const ErrorPoint& b, double target) {
  const double dt = std::log(b.seconds) - std::log(a.seconds);
  const double de = std::log(b.error) - std::log(a.error);
  if (!(dt > 0.0) || !(de < 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::exp(std::log(a.seconds) + (std::log(target) - std::log(a.error)) * dt / de);
}

}  // namespace

TimeToError time_to_error(std::vector<ErrorPoint> points, double target) {
  TimeToError result;
  result.seconds = std::numeric_limits<double>::quiet_NaN();
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const ErrorPoint& p) {
                                return !(p.seconds > 0.0) || !(p.error > 0.0) ||
                                       !std::isfinite(p.seconds) || !std::isfinite(p.error);
                              }),
               points.end());
  if (points.empty() || !(target > 0.0) || !std::isfinite(target)) return result;
  std::sort(points.begin(), points.end(),
            [](const ErrorPoint& a, const ErrorPoint& b) { return a.seconds < b.seconds; });
  if (points.size() == 1) {
    if (points[0].error == target) result.seconds = points[0].seconds;
    return result;
  }
  if (points[0].error <= target) {
    result.extrapolated = points[0].error < target;
    result.seconds = result.extrapolated ? along(points[0], points[1], target) : points[0].seconds;
    // A first segment that does not slope down cannot be followed back: the first point's time
    // is then all that is known (an upper bound).
    if (std::isnan(result.seconds)) result.seconds = points[0].seconds;
    return result;
  }
  for (size_t i = 1; i < points.size(); ++i)
    if (points[i].error <= target) {
      result.seconds = along(points[i - 1], points[i], target);
      if (std::isnan(result.seconds)) result.seconds = points[i].seconds;  // two equal times
      return result;
    }
  result.extrapolated = true;
  result.seconds = along(points[points.size() - 2], points.back(), target);
  return result;
}

}  // namespace pt
