// What the Part 1 tests of steps 3 (triangle) and 4 (sphere) ask of their primitive inside a
// scene, through the given brute-force query (pipeline/1-raygen): each step's checks put only
// its own kind of primitive in the scene, so a bug costs its own step only.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "framework/sampling/rng.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt::test {

/// Appends triangle (a, b, c) to the scene, with per-vertex normals when `normals` is given.
inline void add_scene_triangle(Scene* s, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material,
                               const glm::vec3* normals = nullptr) {
  const uint32_t base = uint32_t(s->positions.size());
  for (const glm::vec3& p : {a, b, c}) s->positions.push_back(p);
  if (normals)
    for (int i = 0; i < 3; ++i) s->normals.push_back(normals[i]);
  s->triangles.push_back(Triangle{{base, base + 1, base + 2}, material});
}

// The error box around every hit point contains a point of the exact surface (long double).
inline void expect_hit_error_bounds_contain_the_exact_surface(bool spheres) {
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
    add_scene_triangle(&s, a, b, c, 0);
    s.spheres.push_back(Sphere{centre + box(size), size * uni(0.1f, 1.0f), 0});
    Ray ray;
    ray.o = centre + box(3 * size) + glm::vec3(0, 0, 4 * size);
    const float u = rng.next_float() * 0.5f, v = rng.next_float() * 0.5f;
    const glm::vec3 at = (trial % 2 == 0) ? a + u * (b - a) + v * (c - a) : s.spheres[0].center;
    ray.d = at - ray.o;
    SurfaceHit hit;
    if ((trial % 2 == 1) != spheres) continue;
    // Only the step's own primitive in the scene: it is primitive 0.
    if (spheres)
      s.triangles.clear();
    else
      s.spheres.clear();
    const uint32_t prim = 0;
    if (!intersect_primitive(s, prim, ray, &hit)) continue;
    EXPECT_EQ(hit.primitive, prim);
    using LD = long double;
    if (!spheres) {
      // The box [p - e, p + e] meets the triangle's plane iff |n·(p - a)| <= sum |n_i| e_i.
      LD n[3], e1[3] = {LD(b.x) - a.x, LD(b.y) - a.y, LD(b.z) - a.z},
               e2[3] = {LD(c.x) - a.x, LD(c.y) - a.y, LD(c.z) - a.z};
      n[0] = e1[1] * e2[2] - e1[2] * e2[1];
      n[1] = e1[2] * e2[0] - e1[0] * e2[2];
      n[2] = e1[0] * e2[1] - e1[1] * e2[0];
      LD dist = 0, reach = 0;
      for (int i = 0; i < 3; ++i)
        dist += n[i] * (LD(hit.p[i]) - a[i]), reach += std::abs(n[i]) * hit.p_error[i];
      EXPECT_LE(std::abs(dist), reach)
          << "trial " << trial << ": the hit point is farther from the triangle's plane than its "
             "p_error says (the error bound of the point you report, triangle_intersect.h)";
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
      EXPECT_LE(near2, r2) << "trial " << trial << ": the sphere lies outside the hit's error box";
      EXPECT_GE(far2, r2) << "trial " << trial << ": the sphere lies outside the hit's error box";
      ++checked_sphere;
    }
    EXPECT_NEAR(glm::length(hit.ng), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(hit.n), 1.0f, 1e-5f);
  }
  std::printf("error boxes: %ld triangle hits, %ld sphere hits checked; the plane needed at most "
              "%.3g of the triangle bound\n",
              checked_tri, checked_sphere, max_used);
  EXPECT_GT(spheres ? checked_sphere : checked_tri, 5000);
}

}  // namespace pt::test
