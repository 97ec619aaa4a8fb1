// Part 4, step 1 (path): a camera ray's radiance is the emission it sees plus what its hit sends
// back after at least one bounce. The bounces are step 2's: each check compares with the
// student's own at_least_one_bounce_radiance on the same random numbers, so a bug of step 2 is on
// both sides and costs this step nothing; one that draws other numbers than rng gives (step 2's
// draws_from_rng_only), and fails the comparison, is charged to step 2 (tests_rest_on_steps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

// Depth 0: the emission the camera sees and nothing else, with one ray.
TEST(path, depth_zero_is_the_emission_seen) {
  test::Rig rig(test::enclosure(0.5f, 1.5f));
  rig.ctx.max_depth = 0;
  Rng rng(1);
  Ray r;
  const glm::vec3 L = estimate_global_illumination(rig.ctx, r, rng);
  EXPECT_TRUE(L == glm::vec3(1.5f))
      << "depth 0 inside a box glowing 1.5 gave " << L.x
      << ": at depth 0 the path is the light seen directly (zero_bounce_radiance)"
      << (L.x == 0.0f ? ", which is missing?" : "");
  EXPECT_EQ(rig.query.intersect_calls, 1) << "only the camera ray is traced at depth 0";
  EXPECT_EQ(rig.query.occluded_calls, 0) << "and no shadow ray";
}

// Depth 1 and more: zero_bounce_radiance at the hit plus at_least_one_bounce_radiance there at
// depth 1; with --bounce K (ctx.only_bounce) the seen emission only for K = 0.
TEST(path, adds_the_emission_seen_to_the_bounces_at_the_hit) {
  test::Rig rig(test::enclosure(0.5f, 1.5f));
  rig.ctx.russian_roulette = false;  // step 3's: the comparison needs none of it
  for (int only : {-1, 0, 1, 2}) {
    for (int depth : {1, 3}) {
      rig.ctx.max_depth = depth;
      rig.ctx.only_bounce = only;
      SCOPED_TRACE("-m " + std::to_string(depth) +
                   (only >= 0 ? ", --bounce " + std::to_string(only) : std::string()));
      for (uint64_t seed = 1; seed <= 4; ++seed) {
        Rng a(seed), b(seed);
        Rng g(seed, 3);
        const Ray r = test::ray_from_inside(g);
        const glm::vec3 seen = only <= 0 ? glm::vec3(1.5f) : glm::vec3(0.0f);
        const glm::vec3 bounces = only == 0 ? glm::vec3(0.0f) : test::bounced_at_hit(rig.ctx, r, b);
        const glm::vec3 got = estimate_global_illumination(rig.ctx, r, a);
        const glm::vec3 want = seen + bounces;
        for (int c = 0; c < 3; ++c)
          ASSERT_TRUE(std::abs(got[c] - want[c]) <= 1e-5f * std::max(1.0f, want[c]))
              << "estimate_global_illumination returned " << got[c] << ", not " << want[c]
              << ": it must be the emission seen (" << seen.x
              << ") plus at_least_one_bounce_radiance at the hit, depth 1 (" << bounces.x
              << "), drawing the same random numbers"
              << (std::abs(got[c] - bounces[c]) < 1e-5f * std::max(1.0f, want[c]) && seen[c] > 0
                      ? ": the light seen directly (zero_bounce_radiance) is missing?"
                      : "");
      }
    }
  }
}

// A camera ray that meets nothing sees the environment in its direction, at every depth, and
// only as the light that took no bounce (--bounce 0, or every bounce).
TEST(path, a_ray_that_escapes_sees_the_environment) {
  Scene s;
  const uint32_t m = test::add_material(s, glm::vec3(0.5f));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  s.lights.push_back(test::ambient_light(glm::vec3(0.7f, 1.3f, 2.1f)));
  test::Rig rig(s);
  rig.ctx.russian_roulette = false;
  Ray away;
  away.o = glm::vec3(0.0f, 0.0f, 3.0f);
  away.d = glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f));
  for (int only : {-1, 0, 2})
    for (int depth : {0, 1, 4}) {
      rig.ctx.max_depth = depth;
      rig.ctx.only_bounce = only;
      Rng rng(2);
      const glm::vec3 L = estimate_global_illumination(rig.ctx, away, rng);
      const glm::vec3 want = only <= 0 ? glm::vec3(0.7f, 1.3f, 2.1f) : glm::vec3(0.0f);
      EXPECT_TRUE(L == want) << "-m " << depth
                             << (only >= 0 ? ", --bounce " + std::to_string(only) : std::string())
                             << ": a camera ray that hits nothing gave (" << L.x << ", " << L.y
                             << ", " << L.z << "), not (" << want.x << ", " << want.y << ", "
                             << want.z << "): an escaping ray sees the environment's radiance "
                             << "in its direction (ctx.lights.environment_radiance), light that "
                             << "took no bounce";
    }
}

}  // namespace
}  // namespace pt
