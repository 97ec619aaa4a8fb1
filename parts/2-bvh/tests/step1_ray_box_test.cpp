// Part 2: the ray-box slab test and the split choices, on their own.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "parts/1-raygen/triangle_intersect.h"
#include "parts/2-bvh/bvh_split.h"
#include "parts/2-bvh/ray_box.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"

namespace pt {
namespace {

const Bounds3 kUnit{glm::vec3(0.0f), glm::vec3(1.0f)};

bool box_hit(const Bounds3& b, glm::vec3 o, glm::vec3 d, float tmin, float tmax, float* t) {
  Ray r;
  r.o = o, r.d = d, r.tmin = tmin;
  return intersect_box(b, BoxRay(r), tmax, t);
}

TEST(Part2RayBox, KnownAnswers) {
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

TEST(Part2RayBox, RaysAlongFacesAndFlatBoxesCount) {
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

TEST(Part2RayBox, NeverLosesAHitToRounding) {
  // Rays aimed at points of small triangles far from the origin, axis-aligned ones among them
  // (flat boxes): wherever the triangle is hit at t, its box must be entered by the distance a
  // traversal culls at (t stretched by kHitDistanceSlack, since t itself is rounded).
  Rng rng(3);
  int hits = 0, lost = 0;
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
    TriangleHit th;
    if (!intersect_triangle(r, p[0], p[1], p[2], &th)) continue;
    ++hits;
    Bounds3 box;
    for (const glm::vec3& q : p) box.grow(q);
    const float bound = th.t * kHitDistanceSlack;
    float t;
    if (!intersect_box(box, BoxRay(r), bound, &t) || t > bound) ++lost;
  }
  EXPECT_GT(hits, 100000);
  EXPECT_EQ(lost, 0);
}

TEST(Part2Split, MidpointCutsTheWidestSpreadInHalf) {
  const MidpointSplit s = midpoint_split(Bounds3{glm::vec3(0, -4, 1), glm::vec3(1, 2, 2)});
  EXPECT_EQ(s.axis, 1);
  EXPECT_FLOAT_EQ(s.position, -1.0f);
  EXPECT_EQ(midpoint_split(Bounds3{glm::vec3(0), glm::vec3(1, 1, 3)}).axis, 2);
}

/// The SAH cost of every plane evaluated directly, plane by plane.
SahSplit naive_sah(const SahBin* bins, int n, float area, const SahCosts& c) {
  SahSplit best;
  for (int p = 0; p < n - 1; ++p) {
    Bounds3 l, r;
    uint32_t nl = 0, nr = 0;
    for (int i = 0; i <= p; ++i) l.grow(bins[i].bounds), nl += bins[i].count;
    for (int i = p + 1; i < n; ++i) r.grow(bins[i].bounds), nr += bins[i].count;
    if (nl == 0 || nr == 0) continue;
    const float cost = c.traversal + c.intersection * (l.surface_area() * nl + r.surface_area() * nr) / area;
    if (cost < best.cost) best = {p, cost};
  }
  return best;
}

TEST(Part2Split, SahSweepAgreesWithPlaneByPlaneCost) {
  Rng rng(17);
  const SahCosts costs{1.0f, 2.0f};
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 2 + int(rng.next_u32() % 15);
    SahBin bins[kMaxSahBins];
    Bounds3 all;
    for (int i = 0; i < n; ++i) {
      if (rng.next_float() < 0.3f) continue;  // empty bins
      bins[i].count = 1 + rng.next_u32() % 20;
      const glm::vec3 lo(float(i) + rng.next_float(), rng.next_float(), rng.next_float());
      bins[i].bounds = Bounds3{lo, lo + glm::vec3(rng.next_float(), rng.next_float(), rng.next_float())};
      all.grow(bins[i].bounds);
    }
    if (all.empty()) continue;
    const float area = all.surface_area();
    const SahSplit got = best_sah_split(bins, n, area, costs), want = naive_sah(bins, n, area, costs);
    ASSERT_EQ(got.plane, want.plane) << "trial " << trial;
    if (want.plane >= 0) {
      ASSERT_NEAR(got.cost, want.cost, 1e-4f * want.cost) << "trial " << trial;
    }
  }
}

TEST(Part2Split, SahHasNoSplitWhenOneBinHoldsEverything) {
  SahBin bins[4];
  bins[2].count = 7;
  bins[2].bounds = kUnit;
  EXPECT_EQ(best_sah_split(bins, 4, kUnit.surface_area(), SahCosts{}).plane, -1);
}

}  // namespace
}  // namespace pt
