// Part 1, step 5 (watertight): intersect_triangle again, held to the rules of its header that the
// renders of later parts need and Part 1's own renders do not show: no ray slips through the
// crack between two triangles (a ray aimed at a shared edge or vertex of a closed mesh hits one
// of them, whatever the rounding), an edge's side is exact where only its products round, and no
// ray hits the triangle it starts on because of rounding alone (a hit counts only where t exceeds
// its own error bound). A correct Möller–Trumbore test,
// the one most courses teach, passes steps 3-4 and the renders, and loses these points only.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

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

// Where the ray's frame involves no rounding (the ray leaves (0, 0, 0) along an axis, so moving and
// shearing the corners is exact), an edge function's only roundings are its two products. Pairs of
// corners almost in line with the origin make those products round to the same float while their
// exact difference is not zero: the ray passes a hair beside the edge, on a side exact arithmetic
// knows. Hit or miss must then be exactly the exact answer; recomputing an edge function that is
// exactly zero in float in double, where products of floats are exact, is what gives it.
TEST(watertight, a_ray_a_hair_beside_an_edge_is_on_its_exact_side) {
  // The sign of a·b - c·d for float factors: their products are exact in double.
  auto exact_sign = [](float a, float b, float c, float d) {
    const double p = double(a) * b, q = double(c) * d;
    return p > q ? 1 : p < q ? -1 : 0;
  };
  Rng rng(29);
  long cases = 0, rays = 0, wrong = 0;
  std::string first;
  while (cases < 1000) {
    const glm::vec2 b(0.5f + 1.5f * rng.next_float(), 0.5f + 1.5f * rng.next_float());
    const float cx = -(0.5f + 1.5f * rng.next_float());
    const glm::vec2 c(cx, float(double(b.y) * cx / b.x));  // about on the line from b through 0
    const float p = b.x * c.y, q = b.y * c.x;
    if (p != q || exact_sign(b.x, c.y, b.y, c.x) == 0) continue;  // not a hair beside it
    ++cases;
    const float s = rng.next_float() < 0.5f ? 1.0f : -1.0f;
    const glm::vec2 a(-b.y * s, b.x * s);  // well off the line, on a random side
    const int e0 = exact_sign(b.x, c.y, b.y, c.x), e1 = exact_sign(c.x, a.y, c.y, a.x),
              e2 = exact_sign(a.x, b.y, a.y, b.x);
    const bool expected = !((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0));
    const glm::vec2 corners[3] = {a, b, c};
    for (int axis = 0; axis < 3; ++axis) {
      for (float dir : {1.0f, -1.0f}) {
        auto place = [&](glm::vec2 uv) {
          glm::vec3 v;
          v[axis] = dir, v[(axis + 1) % 3] = uv.x, v[(axis + 2) % 3] = uv.y;
          return v;
        };
        Ray ray;
        ray.o = glm::vec3(0.0f);
        ray.d = glm::vec3(0.0f);
        ray.d[axis] = dir;
        for (int first_corner = 0; first_corner < 3; ++first_corner) {
          for (int turn : {1, 2}) {  // both windings
            const glm::vec3 p0 = place(corners[first_corner]),
                            p1 = place(corners[(first_corner + turn) % 3]),
                            p2 = place(corners[(first_corner + 2 * turn) % 3]);
            TriangleHit hit;
            const bool got = intersect_triangle(ray, p0, p1, p2, &hit);
            ++rays;
            if (got != expected && ++wrong == 1) {
              char text[320];
              std::snprintf(text, sizeof text,
                            "ray from (0, 0, 0) along (%g, %g, %g), corners (%.9g, %.9g, %.9g) "
                            "(%.9g, %.9g, %.9g) (%.9g, %.9g, %.9g): exact %s, yours %s",
                            ray.d.x, ray.d.y, ray.d.z, p0.x, p0.y, p0.z, p1.x, p1.y, p1.z, p2.x,
                            p2.y, p2.z, expected ? "hit" : "miss", got ? "hit" : "miss");
              first = text;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0) << wrong << " of " << rays
                      << " rays passing a hair beside an edge (its float products round to the "
                         "same value) land on the wrong side of it; the first: "
                      << first
                      << ". Where an edge function is exactly 0 in float, recompute the three in "
                         "double, where products of floats are exact, so its sign is the exact one";
}

}  // namespace
}  // namespace pt
