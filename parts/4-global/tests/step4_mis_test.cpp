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

// CBcoil's panel and light disagree (test::disagreeing_panel_scene): MIS's BSDF samples reach the
// panel and its light samples the same panel, with the light's radiance, so MIS lights the floor
// as light sampling does: ρ·L·F over the panel's rectangle.
TEST(mis, sees_the_panels_shape_with_its_lights_radiance) {
  using P = test::DisagreeingPanel;
  test::Rig rig(test::disagreeing_panel_scene());
  rig.ctx.mis = true;
  rig.ctx.light_samples = 4;
  rig.ctx.max_depth = 1;
  auto floor_point = [](Rng&) {
    Ray r;
    r.o = glm::vec3(0.4f, 0.0f, 0.2f);
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    return r;
  };
  test::expect_mean(test::sample_values(test::gi(rig.ctx), floor_point, 10000, 12),
                    P::floor_radiance(0.4, 0.0), "MIS, direct light on the floor");
}

// The same room with a mirror floor: the camera sees the panel in the mirror with the light's
// radiance under MIS too, as light sampling gives it.
TEST(mis, a_mirror_shows_the_panel_with_its_lights_radiance) {
  using P = test::DisagreeingPanel;
  EXPECT_NEAR(test::panel_in_a_mirror(false, true).x, P::kLightRadiance, 1e-4f);
}

}  // namespace
}  // namespace pt
