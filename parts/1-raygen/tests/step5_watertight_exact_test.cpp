// Part 1, step 5 (watertight), against exact rational arithmetic: the cases a fixed epsilon gets
// wrong (parts/1-raygen/tests/triangle_exactness.h): rays grazing the triangle's plane, triangles
// 1e-4 across (a determinant epsilon misses them), and rays that start just off the triangle and
// hit it at t down to 1e-7 (an epsilon on t misses them); and rays that leave the plane from
// within rounding of it, which must never hit it (only the t error bound tells t = 0 from a hit).
// A test that decides every hit from its own rounding, with t above its own error bound instead
// of a fixed epsilon, gets them all.
#include "parts/1-raygen/tests/triangle_exactness.h"

namespace pt {
namespace {

using test::Cases;
using test::run;
using test::Tally;

TEST(watertight, no_epsilon_loses_grazing_tiny_or_near_hits) {
  Cases cases(13);
  const long n = 12500;
  Tally all;
  all.add(run("grazing", n, [&] { return cases.grazing(); }));
  all.add(run("size 1e-4", n, [&] { return cases.placed(cases.box(1), 1e-4f, 1.0f); }));
  all.add(run("just off the triangle", n, [&] { return cases.just_off(); }));
  const Tally leaving = run("leaving the triangle", n, [&] { return cases.leaving(); }, 0.0, 1.0,
                            /*strict_behind=*/true);
  all.add(leaving);
  print("epsilon cases, all", all);
  EXPECT_GE(all.cases, 50000);
  EXPECT_GT(all.exact_hits, 5000);
  EXPECT_EQ(all.disagreements, 0)
      << " (a grazing, tiny or near hit decided differently from the exact answer, away from "
         "the triangle's edges by more than rounding: a fixed epsilon on the determinant or on t? "
         "Report a hit wherever t is above its own error bound, pbrt-v4 6.8.7)";
  EXPECT_EQ(all.t_over_bound, 0) << " (t further from the exact t than rounding explains)";
  EXPECT_EQ(leaving.behind, 0)
      << " (rays leaving the triangle's plane from within rounding of it hit it again, at a t that "
         "only rounding made: report a hit only where t is above its own error bound, pbrt-v4 "
         "6.8.7)";
}

}  // namespace
}  // namespace pt
