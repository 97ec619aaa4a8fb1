// Not needed for the assignment.
// Time to reach an error, interpolated on log-log axes between measured points.
#include "framework/stats/time_to_error.h"

#include <cmath>

#include <gtest/gtest.h>

namespace pt {
namespace {

TEST(ConvergenceTimeToError, ExactOnAPowerLaw) {
  // error = 0.5 / t: any point of the line is found exactly, wherever the samples fall.
  std::vector<ErrorPoint> pts;
  for (double t : {0.1, 0.4, 3.0, 7.0}) pts.push_back({t, 0.5 / t});
  for (double target : {2.0, 1.0, 0.2, 0.1}) {
    TimeToError r = time_to_error(pts, target);
    EXPECT_NEAR(r.seconds, 0.5 / target, 1e-9 * (0.5 / target)) << target;
    EXPECT_FALSE(r.extrapolated);
  }
}

TEST(ConvergenceTimeToError, InterpolatesInLogSpaceNotLinearly) {
  // From (1 s, 1e-1) to (100 s, 1e-3): 1e-2 lies at 10 s on log-log axes (linear would say 50.5).
  TimeToError r = time_to_error({{100.0, 1e-3}, {1.0, 1e-1}}, 1e-2);
  EXPECT_NEAR(r.seconds, 10.0, 1e-9);
}

TEST(ConvergenceTimeToError, FirstCrossingOfANoisyCurve) {
  // Noise can lift a later point back above the target: the first time it is met counts.
  TimeToError r = time_to_error({{1, 0.1}, {2, 0.04}, {4, 0.06}, {8, 0.01}}, 0.05);
  EXPECT_GT(r.seconds, 1.0);
  EXPECT_LT(r.seconds, 2.0);
}

TEST(ConvergenceTimeToError, OutsideTheMeasuredRangeIsMarkedExtrapolated) {
  std::vector<ErrorPoint> pts = {{1, 1e-1}, {10, 1e-2}};
  TimeToError below = time_to_error(pts, 1e-3);
  EXPECT_TRUE(below.extrapolated);
  EXPECT_NEAR(below.seconds, 100.0, 1e-9);
  TimeToError above = time_to_error(pts, 1.0);
  EXPECT_TRUE(above.extrapolated);
  EXPECT_NEAR(above.seconds, 0.1, 1e-12);
  // Error that does not fall with time never reaches a lower target.
  TimeToError flat = time_to_error({{1, 1e-2}, {10, 1e-2}}, 1e-3);
  EXPECT_TRUE(std::isnan(flat.seconds));
  // Meeting the target exactly at a measured point is not an extrapolation.
  TimeToError at = time_to_error(pts, 1e-1);
  EXPECT_FALSE(at.extrapolated);
  EXPECT_DOUBLE_EQ(at.seconds, 1.0);
}

TEST(ConvergenceTimeToError, UnusablePointsAreIgnored) {
  TimeToError r = time_to_error({{0, 0.5}, {1, NAN}, {1, 1e-1}, {10, 1e-2}, {-3, 1}}, 3e-2);
  EXPECT_FALSE(r.extrapolated);
  EXPECT_NEAR(r.seconds, std::pow(10.0, std::log10(1e-1 / 3e-2)), 1e-9);
  EXPECT_TRUE(std::isnan(time_to_error({}, 0.1).seconds));
  EXPECT_TRUE(std::isnan(time_to_error({{1, 0.1}, {2, 0.05}}, 0.0).seconds));
}

}  // namespace
}  // namespace pt
