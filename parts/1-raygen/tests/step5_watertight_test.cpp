// Part 1, step 5 (watertight): intersect_triangle again, held to the two rules of its header that
// the renders of later parts need and Part 1's own renders do not show: no ray slips through the
// crack between two triangles (a ray aimed at a shared edge or vertex of a closed mesh hits one
// of them, whatever the rounding), and no ray hits the triangle it starts on because of rounding
// alone (a hit counts only where t exceeds its own error bound). A correct Möller–Trumbore test,
// the one most courses teach, passes steps 3-4 and the renders, and loses these points only.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "framework/geometry/spawn_ray.h"
#include "framework/sampling/rng.h"
#include "framework/testing/test_scenes.h"
#include "parts/1-raygen/tests/watertight_rays.h"
#include "parts/1-raygen/triangle_intersect.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt {
namespace {

// 108,000 rays at shared edges and vertices of three closed meshes (small and huge, at the origin
// and 1e5 away): every one must be stopped. The stress run (step3_triangle_stress_test.cpp)
// shoots ten times as many, and shows a float Möller–Trumbore test leaking on such rays.
TEST(watertight, no_ray_slips_between_two_triangles) {
  const test::Count total = test::shoot_all(1500, intersect_triangle);
  EXPECT_GE(total.rays, 100000);
  EXPECT_EQ(total.leaks, 0) << total.leaks << " of " << total.rays
                            << " rays aimed at a shared edge or vertex of a closed mesh hit "
                               "neither triangle: the test is not watertight (Woop, Benthin and "
                               "Wald 2013: shear the triangle into the ray's frame and decide "
                               "the edges on the same numbers for both triangles)";
}

// A ray that leaves a triangle where a ray hit it (spawned from the hit as every bounce and shadow
// ray is: framework/geometry/spawn_ray.h) at a clear angle must not hit that triangle again: the
// t a rounding error makes is below the t error bound.
TEST(watertight, a_ray_leaving_a_triangle_does_not_hit_it_again) {
  Rng rng(17);
  long rays = 0, rehits = 0;
  auto random_unit = [&] {
    return glm::normalize(glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f +
                          glm::vec3(1e-4f));
  };
  for (float distance : {0.0f, 10.0f, 1e3f, 1e5f}) {
    for (int k = 0; k < 2000; ++k) {
      const glm::vec3 centre = distance * random_unit();
      const float size = 0.01f + 10.0f * rng.next_float();
      Scene scene;
      const uint32_t m = test::add_material(scene, glm::vec3(0.5f));
      test::add_triangle(scene, centre + size * random_unit(), centre + size * random_unit(),
                         centre + size * random_unit(), m);
      const glm::vec3 p0 = scene.positions[0], p1 = scene.positions[1], p2 = scene.positions[2];
      const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
      if (!(glm::length(n) > 1e-3f * size * size)) continue;
      float b1 = rng.next_float(), b2 = rng.next_float();
      if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
      const glm::vec3 target = (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
      Ray in;
      in.o = target + 2.0f * size * random_unit();
      in.d = glm::normalize(target - in.o);
      SurfaceHit hit;
      if (!intersect_primitive(scene, 0, in, &hit)) continue;
      glm::vec3 w = random_unit();
      if (std::abs(glm::dot(glm::normalize(n), w)) < 0.2f) continue;  // clear of grazing
      const Ray out = spawn_ray(hit, w);
      TriangleHit again;
      ++rays;
      if (intersect_triangle(out, p0, p1, p2, &again)) ++rehits;
    }
  }
  EXPECT_GT(rays, 4000);
  EXPECT_EQ(rehits, 0) << rehits << " of " << rays
                       << " rays leaving a triangle from its hit point hit it again at a t that "
                          "only rounding made: report a hit only where t is above its error bound "
                          "(pbrt-v4, 6.8.7), not above a fixed epsilon";
}

}  // namespace
}  // namespace pt
