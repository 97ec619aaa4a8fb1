// Part 3, step 2 (zero_bounce): the light a camera ray sees emitted, and only on the side an
// emitter shines to.
#include <gtest/gtest.h>

#include "parts/3-direct/tests/direct_scenes.h"

namespace pt {
namespace {

TEST(zero_bounce, is_the_emission_seen) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f), glm::vec3(2.0f, 3.0f, 4.0f));
  test::add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m);
  test::Rig rig(s);
  Ray r;
  r.o = glm::vec3(0.1f, 0.2f, 1.0f);
  SurfaceHit hit;
  ASSERT_TRUE(rig.query.intersect(r, &hit));
  glm::vec3 L = zero_bounce_radiance(rig.ctx, r, hit);
  EXPECT_EQ(L, glm::vec3(2.0f, 3.0f, 4.0f));
}

TEST(zero_bounce, area_light_panel_glows_on_its_lights_side_only) {
  test::Rig rig(test::panel_under_ceiling());
  Ray up;
  up.o = glm::vec3(0.1f, 0.2f, 0.0f);
  up.d = glm::vec3(0.0f, 0.0f, 1.0f);
  SurfaceHit hit;
  ASSERT_TRUE(rig.query.intersect(up, &hit));
  EXPECT_EQ(zero_bounce_radiance(rig.ctx, up, hit), glm::vec3(5.0f)) << "seen from below";
  Ray down;
  down.o = glm::vec3(0.1f, 0.2f, 0.995f);
  down.d = glm::vec3(0.0f, 0.0f, -1.0f);
  ASSERT_TRUE(rig.query.intersect(down, &hit));
  ASSERT_NEAR(hit.t, 0.005f, 1e-5f) << "the ray should meet the panel's back";
  EXPECT_EQ(zero_bounce_radiance(rig.ctx, down, hit), glm::vec3(0.0f)) << "seen from above";
}

}  // namespace
}  // namespace pt
