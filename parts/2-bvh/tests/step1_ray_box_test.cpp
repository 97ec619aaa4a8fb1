// Part 2, step 1 (ray_box): the conservative ray-box slab test, on known answers, rays along faces
// and flat boxes, and rays that must never be lost to rounding.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/testing/test_scenes.h"
#include "parts/2-bvh/ray_box.h"
#include "pipeline/1-raygen/nearest_hit_query.h"

namespace pt {
namespace {

const Bounds3 kUnit{glm::vec3(0.0f), glm::vec3(1.0f)};

bool box_hit(const Bounds3& b, glm::vec3 o, glm::vec3 d, float tmin, float tmax, float* t) {
  Ray r;
  r.o = o, r.d = d, r.tmin = tmin;
  return intersect_box(b, BoxRay(r), tmax, t);
}

TEST(ray_box, known_answers) {
  const float inf = std::numeric_limits<float>::infinity();
  float t = -1.0f;
  ASSERT_TRUE(box_hit(kUnit, {-1, 0.5f, 0.5f}, {1, 0, 0}, 0, inf, &t));
  EXPECT_LE(t, 1.0f);  // entry rounded down, by a few ulps at most
  EXPECT_GE(t, 1.0f - 1e-6f);
  ASSERT_TRUE(box_hit(kUnit, {0.5f, 0.5f, 0.5f}, {0, 0, 1}, 0, inf, &t));  // from inside
  EXPECT_EQ(t, 0.0f);
  EXPECT_FALSE(box_hit(kUnit, {-1, 0.5f, 0.5f}, {-1, 0, 0}, 0, inf, &t));  // facing away
  EXPECT_FALSE(box_hit(kUnit, {-1, 2.0f, 0.5f}, {1, 0, 0}, 0, inf, &t));   // beside it
  EXPECT_FALSE(box_hit(kUnit, {-1, 0.5f, 0.5f}, {1, 0, 0}, 0, 0.5f, &t));  // ends before it
  EXPECT_FALSE(box_hit(kUnit, {-1, 0.5f, 0.5f}, {1, 0, 0}, 2.5f, inf, &t)); // starts past it
}

TEST(ray_box, rays_along_faces_and_flat_boxes_count) {
  const float inf = std::numeric_limits<float>::infinity();
  float t;
  // In the plane of a face: 0 times infinity, which must not turn the ray away.
  EXPECT_TRUE(box_hit(kUnit, {-1, 1, 0.5f}, {1, 0, 0}, 0, inf, &t));
  EXPECT_TRUE(box_hit(kUnit, {-1, 0, 0}, {1, 0, 0}, 0, inf, &t));  // along an edge
  const Bounds3 flat{glm::vec3(0, 0, 2), glm::vec3(1, 1, 2)};
  ASSERT_TRUE(box_hit(flat, {0.5f, 0.5f, 0}, {0, 0, 1}, 0, inf, &t));
  EXPECT_LE(t, 2.0f);
  EXPECT_TRUE(box_hit(flat, {-1, 0.5f, 2}, {1, 0, 0}, 0, inf, &t));  // inside the flat box's plane
  EXPECT_FALSE(box_hit(flat, {-1, 0.5f, 2.5f}, {1, 0, 0}, 0, inf, &t));
  // -0 directions: 1/-0 is -inf, and the slab must still be either everything or nothing.
  EXPECT_TRUE(box_hit(kUnit, {0.5f, 0.5f, -1}, {-0.0f, -0.0f, 1}, 0, inf, &t));
  EXPECT_FALSE(box_hit(kUnit, {1.5f, 0.5f, -1}, {-0.0f, 0.0f, 1}, 0, inf, &t));
  // -0 along a face: the origin on the plane gives 0 · -inf = NaN for that plane, which must not
  // be paired with the other plane's -inf and lose the box (+0 and -0 must answer alike).
  for (float zero : {0.0f, -0.0f}) {
    EXPECT_TRUE(box_hit(kUnit, {0.5f, 1, -1}, {0, zero, 1}, 0, inf, &t)) << zero;  // on hi plane
    EXPECT_TRUE(box_hit(kUnit, {0.5f, 0, -1}, {0, zero, 1}, 0, inf, &t)) << zero;  // on lo plane
    EXPECT_TRUE(box_hit(flat, {-1, 0.5f, 2}, {1, 0, zero}, 0, inf, &t)) << zero;
  }
}

TEST(ray_box, never_loses_a_hit_to_rounding) {
  // Rays aimed at points of small triangles far from the origin, axis-aligned ones among them
  // (flat boxes): wherever the triangle is hit at t, its box must be entered by the distance a
  // traversal culls at (t stretched by kHitDistanceSlack, since t itself is rounded). Conservative
  // is not "always yes": a ray passing twenty box widths beside the box must miss it. Whether and
  // where the triangle is hit is decided by the test rig's exact query (not Part 1's triangle
  // test, whose valid answers may lie a rounding error outside the triangle's box).
  Rng rng(3);
  int hits = 0, lost = 0, beside = 0, false_hits = 0;
  for (int i = 0; i < 200000; ++i) {
    const float scale = std::ldexp(1.0f, int(rng.next_u32() % 30) - 10);
    const glm::vec3 c = scale * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f) * 8.0f;
    glm::vec3 p[3];
    for (glm::vec3& q : p) q = c + 1e-3f * scale * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f);
    if (i % 3 == 0) p[1][i % 9 / 3] = p[0][i % 9 / 3], p[2][i % 9 / 3] = p[0][i % 9 / 3];
    float a = rng.next_float(), b = rng.next_float();
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const glm::vec3 target = p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
    Ray r;
    r.o = target + scale * square_to_uniform_sphere(rng.next_2d());
    r.d = glm::normalize(target - r.o);
    Scene one;
    test::add_triangle(one, p[0], p[1], p[2], test::add_material(one, glm::vec3(0.5f)));
    const test::DoubleQuery exact(one);
    SurfaceHit th;
    if (!exact.intersect(r, &th)) continue;
    ++hits;
    Bounds3 box;
    for (const glm::vec3& q : p) box.grow(q);
    const float bound = th.t * kHitDistanceSlack;
    float t;
    if (!intersect_box(box, BoxRay(r), bound, &t) || t > bound) ++lost;
    const glm::vec3 side = glm::normalize(glm::cross(r.d, glm::vec3(0.6f, 0.8f, 0.0f) + 1e-3f));
    Ray miss = r;
    miss.d = glm::normalize(target + 0.02f * scale * side - r.o);
    if (std::isfinite(miss.d.x)) {
      ++beside;
      if (intersect_box(box, BoxRay(miss), std::numeric_limits<float>::infinity(), &t)) ++false_hits;
    }
  }
  EXPECT_GT(hits, 100000);
  EXPECT_EQ(lost, 0) << "rays that hit a triangle but, by intersect_box, miss its box (or enter it "
                        "farther than the hit): a box test must be conservative (round the slab "
                        "distances outwards, and compare with <=, so a flat box is still entered)";
  EXPECT_GT(beside, 100000);
  EXPECT_EQ(false_hits, 0) << "intersect_box says yes to rays that pass twenty box widths beside "
                              "the box: a box test must cull what the ray misses";
}

}  // namespace
}  // namespace pt
