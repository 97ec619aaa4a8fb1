// Part 1, step 3 (triangle): the triangle test inside a scene, through the given brute-force
// query: the nearest of stacked triangles within the ray's interval, occlusion, the hit point's
// error bound, and the interpolated normal that decides the outside. Only triangles are in these
// scenes (the sphere's are step 4's), and every ray is made here, not by steps 1-2.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "parts/1-raygen/tests/scene_queries.h"

namespace pt {
namespace {

/// Three big triangles across the -z axis at z = -3, -1 and -2 (primitive i has material -z).
Scene triangle_stack() {
  Scene s;
  for (float z : {-3.0f, -1.0f, -2.0f})
    test::add_scene_triangle(&s, {-10, -10, z}, {10, -10, z}, {0, 10, z}, uint32_t(-z));
  return s;
}

TEST(triangle, brute_force_finds_the_nearest_of_stacked_triangles) {
  Scene s = triangle_stack();
  BruteForce bf(s);
  SurfaceHit hit;
  Ray ray;  // from the origin down -z
  ASSERT_TRUE(bf.intersect(ray, &hit)) << "a ray down the axis through three triangles missed";
  EXPECT_FLOAT_EQ(hit.t, 1.0f) << "the nearest triangle is at t = 1: a farther one reported?";
  EXPECT_EQ(hit.primitive, 1u);
  EXPECT_EQ(hit.material, 1u);
  ray.tmin = 1.5f;  // skip z = -1: the plane at -2, listed last, is next
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f) << "tmin = 1.5: the hit at t = 1 is outside the ray's interval";
  EXPECT_EQ(hit.primitive, 2u);
  ray.tmin = 3.2f;  // past every triangle
  EXPECT_FALSE(bf.intersect(ray, &hit)) << "tmin = 3.2: every triangle is behind the interval";
  ray.tmin = 0.0f;
  ray.tmax = 0.5f;
  EXPECT_FALSE(bf.intersect(ray, &hit)) << "tmax = 0.5: every triangle is beyond the interval";
}

TEST(triangle, occlusion_respects_the_interval) {
  Scene s = triangle_stack();
  BruteForce bf(s);
  Ray ray;
  ray.tmax = 0.99f;
  EXPECT_FALSE(bf.occluded(ray)) << "tmax 0.99, the first triangle at t = 1";
  ray.tmax = 1.01f;
  EXPECT_TRUE(bf.occluded(ray));
  ray.tmin = 3.01f, ray.tmax = 100.0f;
  EXPECT_FALSE(bf.occluded(ray)) << "tmin 3.01, the last triangle at t = 3";
  ray.o = glm::vec3(50, 0, 0);  // beside everything
  ray.tmin = 0.0f;
  EXPECT_FALSE(bf.occluded(ray));
}

// The error box around every triangle hit point contains a point of the exact plane (long
// double).
TEST(triangle, hit_error_bounds_contain_the_exact_surface) {
  test::expect_hit_error_bounds_contain_the_exact_surface(false);
}

TEST(triangle, normals_are_interpolated_and_decide_the_outside) {
  Scene s;
  // Wound so that its winding normal is -z, but the modeller's normals say +z (tilted).
  const glm::vec3 ns[3] = {glm::normalize(glm::vec3(1, 0, 1)), glm::normalize(glm::vec3(0, 1, 1)),
                           glm::vec3(0, 0, 1)};
  test::add_scene_triangle(&s, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0, ns);
  Ray ray;
  ray.o = glm::vec3(0.25f, 0.5f, 1.0f);  // barycentrics (0.25, 0.5, 0.25) for (p0, p1, p2)
  SurfaceHit hit;
  ASSERT_TRUE(intersect_primitive(s, 0, ray, &hit));
  EXPECT_NEAR(glm::length(hit.p - glm::vec3(0.25f, 0.5f, 0.0f)), 0.0f, 1e-6f);
  const glm::vec3 expect = glm::normalize(0.25f * ns[0] + 0.5f * ns[1] + 0.25f * ns[2]);
  EXPECT_NEAR(glm::length(hit.n - expect), 0.0f, 1e-6f)
      << "the shading normal is the vertex normals weighted by the hit's barycentrics (each "
         "corner's weight is the one of its own vertex), normalised: a face normal, or the "
         "weights of the wrong corners?";
  EXPECT_NEAR(glm::length(hit.ng - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);  // flipped to n's side

  // Without vertex normals, n is the winding normal.
  s.normals.clear();
  ASSERT_TRUE(intersect_primitive(s, 0, ray, &hit));
  EXPECT_NEAR(glm::length(hit.ng - glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
  EXPECT_EQ(hit.n, hit.ng);
}

}  // namespace
}  // namespace pt
