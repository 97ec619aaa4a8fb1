// Part 4, step 3 (russian_roulette): paths ended at random stay unbiased, to the known answers of
// scenes that need a thousand bounces.
#include <gtest/gtest.h>

#include <cmath>

#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

TEST(russian_roulette, enclosure_converges_to_e_over_one_minus_rho) {
  const double rho = 0.5, E = 1.0;
  test::Rig rig(test::enclosure(float(rho), float(E)));
  rig.ctx.max_depth = 1000;
  rig.ctx.russian_roulette = true;
  test::expect_mean(test::sample_values(test::gi(rig.ctx), test::ray_from_inside, 20000, 3),
                    E / (1 - rho), "Russian roulette, depth 1000");
  rig.ctx.hemisphere = true;
  test::expect_mean(test::sample_values(test::gi(rig.ctx), test::ray_from_inside, 20000, 5),
                    E / (1 - rho), "hemisphere sampling, Russian roulette, depth 1000");
}

// The design's known answer: a point light of intensity π at the centre of a unit sphere of
// albedo 0.5, seen from inside, has radiance 1 (0.5 direct, doubled by interreflection).
TEST(russian_roulette, point_light_inside_a_diffuse_sphere_gives_radiance_one) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  Light l;
  l.kind = LightKind::point;
  l.radiance = glm::vec3(float(M_PI));
  s.lights.push_back(l);
  test::Rig rig(s);
  rig.ctx.max_depth = 1000;
  test::expect_mean(test::sample_values(test::gi(rig.ctx), test::ray_from_inside, 20000, 8), 1.0,
                    "point light in a sphere");
}

}  // namespace
}  // namespace pt
