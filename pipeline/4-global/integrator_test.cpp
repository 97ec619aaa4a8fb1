// Not needed for the assignment.
// The integrator a render calls: what it chooses for a scene and the settings.
#include "pipeline/4-global/integrator.h"

#include <gtest/gtest.h>

#include <string>

#include "framework/geometry/counting_ray_query.h"
#include "framework/testing/lighting_rig.h"
#include "framework/testing/test_scenes.h"
#include "parts/4-global/global_illumination.h"
#include "pipeline/3-direct/direct_integrator.h"

namespace pt {
namespace {

TEST(PipelineIntegrator, NoLightsAndNoEmittersShowNormalsWithoutShadowRays) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m);
  test::DoubleQuery query(s);
  RenderSettings settings;
  settings.max_depth = 5;
  std::string error;
  auto integrator = Integrator::create(settings, s, query, &error);
  ASSERT_TRUE(integrator) << error;
  EXPECT_TRUE(integrator->shows_normals());
  Ray r;
  r.o = glm::vec3(0, 0, 1);
  Rng rng(1);
  glm::vec3 L = integrator->radiance(r, rng);
  EXPECT_NEAR(L.z, 1.0f, 1e-6f);  // normal (0, 0, 1) shown as (0.5, 0.5, 1)
  EXPECT_EQ(query.occluded_calls, 0);
}

TEST(PipelineIntegrator, AnEnvironmentMapThatCannotBeReadIsNamed) {
  Scene s;
  test::DoubleQuery query(s);
  RenderSettings settings;
  settings.environment_map = "no-such-environment-map.exr";
  std::string error;
  EXPECT_FALSE(Integrator::create(settings, s, query, &error));
  EXPECT_NE(error.find("no-such-environment-map.exr"), std::string::npos) << error;
}

// Parts 3 and 4 render -m 0 and -m 1 alike: the direct integrator that lets Part 3 render without
// Part 4 gives Part 4's answer there, to the bit, on diffuse, mirror and glass surfaces under an
// area light and a sky, whichever bounce is asked for.
TEST(PipelineIntegrator, DirectLightIsThePathEstimateAtDepthsZeroAndOne) {
  Scene s;
  const uint32_t white = test::add_material(s, glm::vec3(0.6f));
  const uint32_t mirror = test::add_material(s, glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::mirror);
  const uint32_t glass = test::add_material(s, glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::glass);
  const uint32_t glow = test::add_material(s, glm::vec3(0.0f), glm::vec3(4.0f));
  s.materials[mirror].reflectance = glm::vec3(0.9f);
  test::add_quad(s, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}, white);
  test::add_quad(s, {-0.5f, -0.5f, 2}, {0.5f, -0.5f, 2}, {0.5f, 0.5f, 2}, {-0.5f, 0.5f, 2}, glow);
  s.spheres.push_back(Sphere{glm::vec3(-1, 0, 0.5f), 0.5f, mirror});
  s.spheres.push_back(Sphere{glm::vec3(1, 0, 0.5f), 0.5f, glass});
  s.lights.push_back(test::ambient_light(glm::vec3(0.3f)));
  test::Rig rig(s);
  long compared = 0;
  for (int depth : {0, 1})
    for (int only : {-1, 0, 1})
      for (bool hemisphere : {false, true}) {
        rig.ctx.max_depth = depth;
        rig.ctx.only_bounce = only;
        rig.ctx.hemisphere = hemisphere;
        Rng make(uint64_t(depth * 10 + only + 1), 3);
        for (int i = 0; i < 300; ++i) {
          Ray r;
          r.o = glm::vec3(make.next_float() * 4 - 2, make.next_float() * 4 - 2, 3.0f);
          r.d = glm::normalize(glm::vec3(make.next_float() - 0.5f, make.next_float() - 0.5f, -1.0f));
          Rng a(7, uint64_t(i)), b(7, uint64_t(i));
          const glm::vec3 direct = estimate_direct_illumination(rig.ctx, r, a);
          const glm::vec3 path = estimate_global_illumination(rig.ctx, r, b);
          ASSERT_EQ(direct, path) << "depth " << depth << ", bounce " << only << ", ray " << i;
          ASSERT_EQ(a.next_u32(), b.next_u32()) << "the same random numbers were drawn";
          ++compared;
        }
      }
  EXPECT_EQ(compared, 2 * 3 * 2 * 300);
}

// A render hands each camera sample a counter of its own around the query; the estimate through it
// is the integrator's own, to the bit, whatever the settings (a setting the per-sample context
// failed to carry over would change it), and the counter sees every ray.
TEST(PipelineIntegrator, ASampleTracedThroughAnotherQueryGivesTheSameEstimate) {
  Scene s;
  const uint32_t white = test::add_material(s, glm::vec3(0.6f));
  const uint32_t glow = test::add_material(s, glm::vec3(0.0f), glm::vec3(4.0f));
  test::add_quad(s, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}, white);
  test::add_quad(s, {-3, -3, 0}, {-3, 3, 0}, {-3, 3, 3}, {-3, -3, 3}, white);
  test::add_quad(s, {-0.5f, -0.5f, 2}, {0.5f, -0.5f, 2}, {0.5f, 0.5f, 2}, {-0.5f, 0.5f, 2}, glow);
  test::DoubleQuery query(s);
  long compared = 0;
  for (int light_samples : {1, 3})
    for (bool hemisphere : {false, true})
      for (bool mis : {false, true})
        for (int depth : {1, 4})
          for (bool roulette : {true, false})
            for (int only : {-1, 2}) {
              RenderSettings settings;
              settings.light_samples = light_samples;
              settings.hemisphere_sampling = hemisphere;
              settings.mis = mis;
              settings.max_depth = depth;
              settings.russian_roulette = roulette;
              settings.only_bounce = only;
              std::string error;
              auto integrator = Integrator::create(settings, s, query, &error);
              ASSERT_TRUE(integrator) << error;
              Rng make(uint64_t(compared + 1), 5);
              for (int i = 0; i < 20; ++i) {
                Ray r;
                r.o = glm::vec3(make.next_float() * 4 - 2, make.next_float() * 4 - 2, 2.5f);
                r.d = glm::normalize(
                    glm::vec3(make.next_float() - 0.5f, make.next_float() - 0.5f, -1.0f));
                Rng a(9, uint64_t(i)), b(9, uint64_t(i));
                const long before = query.intersect_calls + query.occluded_calls;
                const glm::vec3 own = integrator->radiance(r, a);
                const long traced = query.intersect_calls + query.occluded_calls - before;
                const LocalCountingRayQuery<RayQuery> counted(query);
                const glm::vec3 through = integrator->radiance(r, b, counted);
                ASSERT_EQ(own, through) << "settings " << compared / 20 << ", ray " << i;
                ASSERT_EQ(a.next_u32(), b.next_u32()) << "the same random numbers were drawn";
                ASSERT_EQ(counted.count(), uint64_t(traced));
                ++compared;
              }
            }
  EXPECT_EQ(compared, 64 * 20);
}

}  // namespace
}  // namespace pt
