// Part 1: brute-force scene queries — nearest hit, occlusion, hit points and their error bounds,
// normals.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "framework/sampling/rng.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt {
namespace {

/// Appends triangle (a, b, c) to the scene, with per-vertex normals when `normals` is given.
void add_triangle(Scene* s, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material,
                  const glm::vec3* normals = nullptr) {
  const uint32_t base = uint32_t(s->positions.size());
  for (const glm::vec3& p : {a, b, c}) s->positions.push_back(p);
  if (normals)
    for (int i = 0; i < 3; ++i) s->normals.push_back(normals[i]);
  s->triangles.push_back(Triangle{{base, base + 1, base + 2}, material});
}

/// Three big triangles across the -z axis at z = -3, -1 and -2, and two spheres on it.
Scene stack() {
  Scene s;
  for (float z : {-3.0f, -1.0f, -2.0f})
    add_triangle(&s, {-10, -10, z}, {10, -10, z}, {0, 10, z}, uint32_t(-z));
  s.spheres.push_back(Sphere{glm::vec3(0, 0, -6), 1.0f, 6});
  s.spheres.push_back(Sphere{glm::vec3(0, 0, -4.5f), 1.0f, 7});  // overlaps the first sphere
  return s;
}

TEST(scene, brute_force_finds_the_nearest_of_overlapping_primitives) {
  Scene s = stack();
  BruteForce bf(s);
  SurfaceHit hit;
  Ray ray;  // from the origin down -z
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 1.0f);
  EXPECT_EQ(hit.primitive, 1u);
  EXPECT_EQ(hit.material, 1u);
  ray.tmin = 1.5f;  // skip z = -1: the plane at -2, listed last, is next
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
  EXPECT_EQ(hit.primitive, 2u);
  ray.tmin = 3.2f;  // past the planes: the nearer sphere's front at 3.5
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 3.5f);
  EXPECT_EQ(hit.primitive, 4u);
  EXPECT_EQ(hit.material, 7u);
  ray.tmin = 5.2f;  // inside both spheres: the far side of the nearer one at 5.5
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 5.5f);
  EXPECT_EQ(hit.primitive, 4u);
  ray.tmin = 5.6f;  // inside the first sphere only: its far side at 7
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 7.0f);
  EXPECT_EQ(hit.primitive, 3u);
  ray.tmin = 7.5f;
  EXPECT_FALSE(bf.intersect(ray, &hit));
}

TEST(scene, occlusion_respects_the_interval) {
  Scene s = stack();
  BruteForce bf(s);
  Ray ray;
  ray.tmax = 0.99f;
  EXPECT_FALSE(bf.occluded(ray));
  ray.tmax = 1.01f;
  EXPECT_TRUE(bf.occluded(ray));
  ray.tmin = 7.01f, ray.tmax = 100.0f;
  EXPECT_FALSE(bf.occluded(ray));
  ray.o = glm::vec3(50, 0, 0);  // beside everything
  ray.tmin = 0.0f;
  EXPECT_FALSE(bf.occluded(ray));
}

// The error box around every hit point contains a point of the exact surface (long double).
TEST(scene, hit_error_bounds_contain_the_exact_surface) {
  Rng rng(23);
  auto uni = [&](float lo, float hi) { return lo + (hi - lo) * rng.next_float(); };
  auto box = [&](float r) { return glm::vec3(uni(-r, r), uni(-r, r), uni(-r, r)); };
  long checked_tri = 0, checked_sphere = 0;
  double max_used = 0;  // how much of the bound the exact surface needed, at most
  for (int trial = 0; trial < 20000; ++trial) {
    const float far = std::pow(10.0f, uni(0, 5));
    const glm::vec3 centre = far * glm::normalize(box(1) + glm::vec3(1e-3f));
    const float size = std::pow(10.0f, uni(-2, 2));
    Scene s;
    const glm::vec3 a = centre + box(size), b = centre + box(size), c = centre + box(size);
    add_triangle(&s, a, b, c, 0);
    s.spheres.push_back(Sphere{centre + box(size), size * uni(0.1f, 1.0f), 0});
    Ray ray;
    ray.o = centre + box(3 * size) + glm::vec3(0, 0, 4 * size);
    const float u = rng.next_float() * 0.5f, v = rng.next_float() * 0.5f;
    const glm::vec3 at = (trial % 2 == 0) ? a + u * (b - a) + v * (c - a) : s.spheres[0].center;
    ray.d = at - ray.o;
    SurfaceHit hit;
    const uint32_t prim = uint32_t(trial % 2);
    if (!intersect_primitive(s, prim, ray, &hit)) continue;
    EXPECT_EQ(hit.primitive, prim);
    using LD = long double;
    if (prim == 0) {
      // The box [p - e, p + e] meets the triangle's plane iff |n·(p - a)| <= sum |n_i| e_i.
      LD n[3], e1[3] = {LD(b.x) - a.x, LD(b.y) - a.y, LD(b.z) - a.z},
               e2[3] = {LD(c.x) - a.x, LD(c.y) - a.y, LD(c.z) - a.z};
      n[0] = e1[1] * e2[2] - e1[2] * e2[1];
      n[1] = e1[2] * e2[0] - e1[0] * e2[2];
      n[2] = e1[0] * e2[1] - e1[1] * e2[0];
      LD dist = 0, reach = 0;
      for (int i = 0; i < 3; ++i)
        dist += n[i] * (LD(hit.p[i]) - a[i]), reach += std::abs(n[i]) * hit.p_error[i];
      EXPECT_LE(std::abs(dist), reach) << "trial " << trial;
      max_used = std::max(max_used, double(std::abs(dist) / reach));
      ++checked_tri;
    } else {
      // The box meets the sphere iff its nearest point is within r and its farthest beyond r.
      const Sphere& sp = s.spheres[0];
      LD near2 = 0, far2 = 0;
      for (int i = 0; i < 3; ++i) {
        LD lo = LD(hit.p[i]) - hit.p_error[i] - sp.center[i];
        LD hi = LD(hit.p[i]) + hit.p_error[i] - sp.center[i];
        LD nearest = (lo > 0) ? lo : (hi < 0 ? hi : 0);
        near2 += nearest * nearest;
        far2 += std::max(lo * lo, hi * hi);
      }
      const LD r2 = LD(sp.radius) * sp.radius;
      EXPECT_LE(near2, r2) << "trial " << trial;
      EXPECT_GE(far2, r2) << "trial " << trial;
      ++checked_sphere;
    }
    EXPECT_NEAR(glm::length(hit.ng), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(hit.n), 1.0f, 1e-5f);
  }
  std::printf("error boxes: %ld triangle hits, %ld sphere hits checked; the plane needed at most "
              "%.3g of the triangle bound\n",
              checked_tri, checked_sphere, max_used);
  EXPECT_GT(checked_tri, 5000);
  EXPECT_GT(checked_sphere, 5000);
}

TEST(scene, normals_are_interpolated_and_decide_the_outside) {
  Scene s;
  // Wound so that its winding normal is -z, but the modeller's normals say +z (tilted).
  const glm::vec3 ns[3] = {glm::normalize(glm::vec3(1, 0, 1)), glm::normalize(glm::vec3(0, 1, 1)),
                           glm::vec3(0, 0, 1)};
  add_triangle(&s, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0, ns);
  Ray ray;
  ray.o = glm::vec3(0.25f, 0.5f, 1.0f);  // barycentrics (0.25, 0.5, 0.25) for (p0, p1, p2)
  SurfaceHit hit;
  ASSERT_TRUE(intersect_primitive(s, 0, ray, &hit));
  EXPECT_NEAR(glm::length(hit.p - glm::vec3(0.25f, 0.5f, 0.0f)), 0.0f, 1e-6f);
  const glm::vec3 expect = glm::normalize(0.25f * ns[0] + 0.5f * ns[1] + 0.25f * ns[2]);
  EXPECT_NEAR(glm::length(hit.n - expect), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(hit.ng - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);  // flipped to n's side

  // Without vertex normals, n is the winding normal.
  s.normals.clear();
  ASSERT_TRUE(intersect_primitive(s, 0, ray, &hit));
  EXPECT_NEAR(glm::length(hit.ng - glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
  EXPECT_EQ(hit.n, hit.ng);

  // A sphere's normal points out, whichever side the ray comes from.
  Scene sp;
  sp.spheres.push_back(Sphere{glm::vec3(0, 0, -5), 2.0f, 0});
  Ray inside;
  inside.o = glm::vec3(0, 0, -5);
  inside.d = glm::vec3(0, 1, 0);
  ASSERT_TRUE(intersect_primitive(sp, 0, inside, &hit));
  EXPECT_NEAR(glm::length(hit.n - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(hit.p - glm::vec3(0, 2, -5)), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace pt
