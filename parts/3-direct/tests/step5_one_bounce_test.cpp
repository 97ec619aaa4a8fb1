// Part 3, step 5 (one_bounce): one_bounce_radiance hands the shading point to the estimator the
// settings name (ctx.hemisphere), and gives a specular surface nothing. It is compared with the
// very estimator it should call, on the same random numbers, so a bug inside step 3's or step 4's
// estimator does not cost this step; only an estimator that returns nothing at a lit point
// (its stub) leaves the test unable to tell, and then it says so.
#include <gtest/gtest.h>

#include "parts/3-direct/tests/direct_scenes.h"

namespace pt {
namespace {

/// The floor under panel_under_ceiling's light, and a ray down at it.
Scene floor_under_panel(MaterialKind floor_kind) {
  Scene s = test::panel_under_ceiling();
  const uint32_t floor = test::add_material(s, glm::vec3(0.5f), glm::vec3(0.0f), floor_kind);
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  return s;
}

Ray ray_down_at_floor() {
  Ray r;
  r.o = glm::vec3(0.1f, -0.1f, 0.5f);
  r.d = glm::vec3(0.0f, 0.0f, -1.0f);
  return r;
}

// At the lit floor and at the light's own panel (an emitter: what it emits is
// zero_bounce_radiance's, counted where the camera or a hemisphere ray sees it, never again here).
TEST(one_bounce, calls_the_estimator_the_settings_name) {
  test::Rig rig(floor_under_panel(MaterialKind::diffuse));
  rig.ctx.light_samples = 4;
  bool any_light = false;
  for (bool at_panel : {false, true}) {
    Ray r = ray_down_at_floor();
    if (at_panel) r.d = glm::vec3(0.0f, 0.0f, 1.0f);
    SurfaceHit hit;
    ASSERT_TRUE(rig.query.intersect(r, &hit));
    const test::RigPoint p(rig.ctx.scene, r, hit);
    for (bool hemisphere : {true, false}) {
      const char* name = hemisphere ? "estimate_direct_hemisphere (step 3)"
                                    : "estimate_direct_importance (step 4)";
      SCOPED_TRACE(std::string(at_panel ? "at the light's panel" : "at the lit floor") +
                   ", ctx.hemisphere = " + (hemisphere ? "true" : "false"));
      rig.ctx.hemisphere = hemisphere;
      for (uint64_t seed = 1; seed <= 8; ++seed) {
        Rng a(seed), b(seed);
        const glm::vec3 expected = hemisphere ? estimate_direct_hemisphere(rig.ctx, p.point, b)
                                              : estimate_direct_importance(rig.ctx, p.point, b);
        any_light = any_light || expected != glm::vec3(0.0f);
        const glm::vec3 got = one_bounce_radiance(rig.ctx, p.point, a);
        ASSERT_TRUE(got == expected)
            << "one_bounce_radiance returned (" << got.x << ", " << got.y << ", " << got.z
            << ") where " << name << " returned (" << expected.x << ", " << expected.y << ", "
            << expected.z << "): it must return " << name
            << "'s estimate (the same random numbers give the same value)"
            << (at_panel && got.x > expected.x
                    ? ": more at an emitter: its emission counted twice? (the light a surface "
                      "emits is zero_bounce_radiance's, counted once where it is seen)"
                    : "");
        ASSERT_TRUE(a.next_float() == b.next_float())
            << "one_bounce_radiance drew other random numbers than " << name << " alone";
      }
    }
  }
  EXPECT_TRUE(any_light)
      << "this test rests on steps 3 and 4: both estimators returned 0 at a lit floor point, so "
         "one_bounce_radiance cannot be told from a stub (are they written yet?)";
}

TEST(one_bounce, a_mirror_gets_no_light_sample) {
  // No light sample can reach a mirror's one direction: zero, and no ray traced to find it out.
  test::Rig rig(floor_under_panel(MaterialKind::mirror));
  rig.ctx.light_samples = 4;
  const Ray r = ray_down_at_floor();
  SurfaceHit hit;
  ASSERT_TRUE(rig.query.intersect(r, &hit));
  const test::RigPoint p(rig.ctx.scene, r, hit);
  ASSERT_TRUE(p.point.bsdf->is_delta());
  for (bool hemisphere : {true, false}) {
    rig.ctx.hemisphere = hemisphere;
    rig.query.intersect_calls = rig.query.occluded_calls = 0;
    Rng rng(3);
    EXPECT_EQ(one_bounce_radiance(rig.ctx, p.point, rng), glm::vec3(0.0f));
    EXPECT_EQ(rig.query.intersect_calls + rig.query.occluded_calls, 0)
        << (hemisphere ? "hemisphere" : "light")
        << " sampling at a mirror: is_delta() says no sample can count, so trace nothing";
  }
  // ...while the diffuse floor of the same room does get light (a zero alone proves nothing).
  test::Rig lit(floor_under_panel(MaterialKind::diffuse));
  SurfaceHit h;
  ASSERT_TRUE(lit.query.intersect(r, &h));
  const test::RigPoint q(lit.ctx.scene, r, h);
  Rng rng(4);
  EXPECT_GT(one_bounce_radiance(lit.ctx, q.point, rng).x, 0.0f)
      << "one_bounce_radiance at a lit diffuse floor (light sampling, step 4) returned nothing";
}

}  // namespace
}  // namespace pt
