// Not needed for the assignment.
// When a strategy reaches a given error: log-log interpolation along its measured
// (seconds, error) points, to compare strategies at equal error rather than equal samples.
#pragma once

#include <vector>

namespace pt {

/// One measurement of a strategy: a render that took `seconds` and had `error`.
struct ErrorPoint {
  double seconds = 0.0;
  double error = 0.0;
};

/// When the error is first expected to reach the target. Error falls as a power of time for an
/// unbiased estimator (relMSE ∝ 1/t), so straight lines on log-log axes are the right interpolant.
struct TimeToError {
  double seconds = 0.0;       ///< NaN when it cannot be told
  bool extrapolated = false;  ///< beyond the measured points, along the nearest segment
};

/// Sorts the points by time and finds the first segment whose error falls to `target`, and
/// interpolates it on log-log axes. When the first point already meets the target, or none does,
/// the nearest segment's line is followed out of the measured range and the answer is marked
/// extrapolated; if that line does not slope down, the answer is the first point's time (target
/// met at once) or NaN (never met). Points with non-positive or non-finite values are ignored.
TimeToError time_to_error(std::vector<ErrorPoint> points, double target);

}  // namespace pt
