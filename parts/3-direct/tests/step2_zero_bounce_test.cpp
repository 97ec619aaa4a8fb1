// Part 3, step 2 (zero_bounce): the light a camera ray sees emitted, only on the side an emitter
// shines to, and from the emitter light sampling samples.
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

// CBcoil's panel and light disagree (test::disagreeing_panel_scene). The camera sees the panel's
// shape glowing with the light's radiance, from below only; where the light reaches beyond the
// panel there is nothing to see.
TEST(zero_bounce, the_camera_sees_the_panels_shape_with_its_lights_radiance) {
  using P = test::DisagreeingPanel;
  test::Rig rig(test::disagreeing_panel_scene());
  auto look = [&](float x, float y, float z, float dz, SurfaceHit* hit) {
    Ray r;
    r.o = glm::vec3(x, y, z);
    r.d = glm::vec3(0.0f, 0.0f, dz);
    return rig.query.intersect(r, hit) ? zero_bounce_radiance(rig.ctx, r, *hit) : glm::vec3(-1.0f);
  };
  SurfaceHit hit;
  EXPECT_EQ(look(0.1f, 0.1f, 0.2f, 1.0f, &hit), glm::vec3(P::kLightRadiance)) << "the panel from below";
  EXPECT_EQ(look(0.35f, 0.0f, 0.2f, 1.0f, &hit), glm::vec3(P::kLightRadiance))
      << "the panel where the light does not reach";
  EXPECT_EQ(look(0.0f, 0.35f, 0.2f, 1.0f, &hit), glm::vec3(-1.0f))
      << "where only the light reaches, nothing is there to be seen";
  EXPECT_EQ(look(0.1f, 0.1f, 0.7f, -1.0f, &hit), glm::vec3(0.0f)) << "the panel from above";
}

}  // namespace
}  // namespace pt
