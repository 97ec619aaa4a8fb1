// Part 1, step 3 (triangle): intersect_triangle against exact rational arithmetic (CGAL's Gmpq,
// parts/1-raygen/tests/triangle_exactness.h says where rounding may decide and why). Any correct
// test, watertight or a Möller–Trumbore without epsilons, agrees with the exact answer wherever
// rounding cannot decide it. The cases a fixed epsilon gets wrong (grazing rays, triangles 1e-4
// across, hits at t below 0.001) are step 5's (step5_watertight_exact_test.cpp), so an epsilon costs
// the watertight step only.
#include "parts/1-raygen/tests/triangle_exactness.h"

namespace pt {
namespace {

using test::Cases;
using test::run;
using test::Tally;

/// Step 3 leaves hits at t below this to step 5 (a fixed epsilon on t misses them).
constexpr double kLeastT = 1e-3;
/// Step 3 takes a t within this many times the watertight test's rounding bound: any correct
/// float test's t (a Möller–Trumbore test's strays up to a few times it on large triangles); a
/// wrong formula is off by far more. Step 5 holds the watertight test to the bound itself.
constexpr double kTSlack = 64.0;

const char* const kDisagree =
    " (a hit where the exact answer misses, or a miss where it hits, away from every edge by more "
    "than rounding can move it: is the hit inside all three edges, in front of tmin and before "
    "tmax?)";

TEST(triangle, random_rays_agree_with_exact_arithmetic) {
  Cases cases(7);
  Tally t = run("random", 100000, [&] { return cases.random(); }, kLeastT, kTSlack);
  EXPECT_EQ(t.disagreements, 0) << kDisagree;
  EXPECT_EQ(t.t_over_bound, 0) << " (t further from the exact t than any float test's rounding "
                                   "explains: is t computed from the same numbers as the hit?)";
  EXPECT_GT(t.exact_hits, 10000);  // the cases do exercise hits
  // Random rays rarely come within rounding of an edge: the exclusion must stay rare there.
  EXPECT_LT(t.near_edge + t.near_t_end, t.cases / 100);
}

TEST(triangle, adversarial_rays_agree_with_exact_arithmetic) {
  Cases cases(11);
  const long n = 12500;
  Tally all;
  all.add(run("through edges and vertices", n, [&] { return cases.edge_or_vertex(); }, kLeastT, kTSlack));
  all.add(run("1e5 from the origin", n, [&] {
    return cases.placed(1e5f * cases.unit(), 10.0f, 20.0f);
  }, kLeastT, kTSlack));
  all.add(run("at 1e5, origin at 0", n, [&] {
    return cases.placed(1e5f * cases.unit(), 100.0f, 1e5f);
  }, kLeastT, kTSlack));
  all.add(run("size 1e4", n, [&] { return cases.placed(cases.box(10), 1e4f, 3e3f); }, kLeastT, kTSlack));
  all.add(run("needles", n, [&] { return cases.needle(); }, kLeastT, kTSlack));
  all.add(run("degenerate", n, [&] { return cases.degenerate(); }, kLeastT, kTSlack));
  print("adversarial, all", all);
  EXPECT_GE(all.cases, 75000);
  EXPECT_EQ(all.disagreements, 0) << kDisagree;
  EXPECT_EQ(all.t_over_bound, 0) << " (t further from the exact t than any float test's rounding "
                                     "explains: is t computed from the same numbers as the hit?)";
}

}  // namespace
}  // namespace pt
