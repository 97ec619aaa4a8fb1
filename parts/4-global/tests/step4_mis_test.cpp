// Part 4, step 4 (mis): the power heuristic on hand-computed cases, and direct light by light and
// BSDF samples weighted by it stays unbiased along whole paths.
#include <gtest/gtest.h>

#include <limits>

#include "parts/4-global/mis.h"
#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

TEST(mis, power_heuristic_on_hand_computed_cases) {
  EXPECT_FLOAT_EQ(power_heuristic(1, 1.0f, 1, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(power_heuristic(2, 1.0f, 1, 1.0f), 0.8f);    // (2·1)² / ((2·1)² + 1²)
  EXPECT_FLOAT_EQ(power_heuristic(1, 2.0f, 4, 1.0f), 0.2f);    // 2² / (2² + 4²)
  EXPECT_FLOAT_EQ(power_heuristic(1, 2.0f, 1, 0.0f), 1.0f);    // only strategy a draws it
  EXPECT_FLOAT_EQ(power_heuristic(1, 0.0f, 1, 2.0f), 0.0f);
  EXPECT_FLOAT_EQ(power_heuristic(1, 0.0f, 1, 0.0f), 0.0f) << "no strategy draws it: no NaN";
  EXPECT_FLOAT_EQ(power_heuristic(1, std::numeric_limits<float>::infinity(), 1, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(power_heuristic(1, 1e30f, 1, 1.0f), 1.0f) << "a² overflows: still 1, no NaN";
  // The weights of the two strategies for one sample add up to 1.
  EXPECT_FLOAT_EQ(power_heuristic(3, 0.7f, 2, 1.9f) + power_heuristic(2, 1.9f, 3, 0.7f), 1.0f);
}

TEST(mis, enclosure_converges_to_e_over_one_minus_rho) {
  const double rho = 0.5, E = 1.0;
  test::Rig rig(test::enclosure(float(rho), float(E)));
  rig.ctx.max_depth = 1000;
  rig.ctx.russian_roulette = true;
  rig.ctx.mis = true;
  test::expect_mean(test::sample_values(test::gi(rig.ctx), test::ray_from_inside, 20000, 4),
                    E / (1 - rho), "MIS, Russian roulette, depth 1000");
}

}  // namespace
}  // namespace pt
