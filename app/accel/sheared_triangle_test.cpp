// The wide BVH's triangle test (shear once per ray) against Part 1's intersect_triangle: the same
// answer and bit-identical t and barycentrics on millions of random and adversarial rays; and its
// four-triangle SIMD filter never turns away a triangle that test accepts; and the four-triangle
// SIMD test, where it answers rather than hand a lane back, answers bit for bit as that test, as
// does the eight-triangle one (AVX) lane for lane.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "app/accel/sheared_triangle.h"
#include "app/accel/triangle4.h"
#include "framework/math/float_error.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "parts/1-raygen/triangle_intersect.h"

namespace pt {
namespace {

glm::vec3 random_in_cube(Rng& rng, float half) {
  return half * (2.0f * glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 1.0f);
}

/// Counts of one comparison run, and the first disagreement described.
struct Tally {
  size_t cases = 0, hits = 0, differ = 0;
  size_t filtered = 0, filter_lost = 0;  ///< lanes the four-triangle filter rejected; wrongly
  /// Hits the four-triangle test answered itself, handed to the scalar test, got wrong.
  size_t simd_hits = 0, simd_retests = 0, simd_differ = 0;
  /// Hits of the eight-lane test, and lanes where it did not answer as the four-lane test.
  size_t eight_hits = 0, eight_differ = 0;
  std::string first;
};

void compare(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
             Tally* tally) {
  TriangleHit want, got;
  const bool hw = intersect_triangle(ray, p0, p1, p2, &want);
  float got_error = 0.0f;
  const bool hg =
      intersect_sheared_triangle(ShearedRay(ray), ray.tmax, p0, p1, p2, &got, &got_error);
  ++tally->cases;
  tally->hits += hw;
  // The same triangle in one lane of a packet (which lane varies), the others empty (NaN).
  Triangle4 packet;
  const int lane = int(tally->cases % 4);
  const glm::vec3* corners[3] = {&p0, &p1, &p2};
  for (int v = 0; v < 3; ++v)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 4; ++k)
        packet.corner[v][a][k] = k == lane ? (*corners[v])[a] : std::nanf("");
  const bool candidate =
      (triangle4_candidates(packet, ShearedRay4(ShearedRay(ray)), ray.tmax) >> lane) & 1u;
  tally->filtered += !candidate;
  // The whole test in SIMD lanes: a hit lane carries the scalar test's very values, and stays a
  // hit for a nearer tmax exactly when the scalar test says so; a lane neither hit nor handed
  // back is one the scalar test misses.
  Triangle4Hits h4;
  const ShearedRay4 ray4(ray);
  triangle4_intersect(packet, ray4, ray.tmax, 0xFu, &h4);
  bool simd_same = true;
  if (h4.hit >> lane & 1u) {
    ++tally->simd_hits;
    simd_same = hg && float_to_bits(h4.t[lane]) == float_to_bits(got.t) &&
                float_to_bits(h4.b0[lane]) == float_to_bits(got.b0) &&
                float_to_bits(h4.b1[lane]) == float_to_bits(got.b1) &&
                float_to_bits(h4.b2[lane]) == float_to_bits(got.b2) &&
                float_to_bits(h4.t_error[lane]) == float_to_bits(got_error);
    for (float tmax : {got.t, next_float_down(got.t), next_float_up(got.t),
                       0.5f * (ray.tmin + got.t)}) {
      TriangleHit unused;
      simd_same &= h4.still_hits(uint32_t(lane), tmax) ==
                   intersect_sheared_triangle(ray4.r, tmax, p0, p1, p2, &unused);
    }
  } else if (h4.retest >> lane & 1u) {
    ++tally->simd_retests;
  } else {
    simd_same = !hg;
  }
  if (!simd_same && tally->simd_differ++ == 0)
    tally->first += " [four-lane test differs: t=" + std::to_string(got.t) + "]";
  // The eight-lane test (two packets, AVX where the build has it) answers every lane as the
  // four-lane test does: the same triangle in lane `lane8` of two packets, the rest empty.
  Triangle4 pair[2];
  const int lane8 = int(tally->cases % 8);
  for (int v = 0; v < 3; ++v)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 8; ++k)
        pair[k / 4].corner[v][a][k % 4] = k == lane8 ? (*corners[v])[a] : std::nanf("");
  Triangle4 single;
  for (int v = 0; v < 3; ++v)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 4; ++k) single.corner[v][a][k] = pair[lane8 / 4].corner[v][a][k];
  Triangle8Hits h8;
  triangle8_intersect(pair[0], pair[1], ray4, ray.tmax, 0xFFu, &h8);
  Triangle4Hits h1;
  triangle4_intersect(single, ray4, ray.tmax, 0xFu, &h1);
  const unsigned shift = unsigned(lane8 / 4) * 4u, l1 = unsigned(lane8 % 4);
  bool same8 = (h8.hit >> shift & 0xFu) == h1.hit && (h8.retest >> shift & 0xFu) == h1.retest;
  if (same8 && (h1.hit >> l1 & 1u))
    same8 = float_to_bits(h8.t[lane8]) == float_to_bits(h1.t[l1]) &&
            float_to_bits(h8.b0[lane8]) == float_to_bits(h1.b0[l1]) &&
            float_to_bits(h8.b1[lane8]) == float_to_bits(h1.b1[l1]) &&
            float_to_bits(h8.b2[lane8]) == float_to_bits(h1.b2[l1]) &&
            float_to_bits(h8.t_error[lane8]) == float_to_bits(h1.t_error[l1]) &&
            h8.still_hits(uint32_t(lane8), 0.5f * (ray.tmin + h1.t[l1])) ==
                h1.still_hits(l1, 0.5f * (ray.tmin + h1.t[l1]));
  tally->eight_hits += (h8.hit >> lane8) & 1u;
  if (!same8 && tally->eight_differ++ == 0)
    tally->first += " [eight-lane test differs from four-lane: t=" + std::to_string(got.t) + "]";
  if (hg && !candidate && tally->filter_lost++ == 0)
    tally->first += " [filter rejected a hit at t=" + std::to_string(got.t) + "]";
  const bool same = hw == hg && (!hw || (float_to_bits(want.t) == float_to_bits(got.t) &&
                                         float_to_bits(want.b0) == float_to_bits(got.b0) &&
                                         float_to_bits(want.b1) == float_to_bits(got.b1) &&
                                         float_to_bits(want.b2) == float_to_bits(got.b2)));
  if (!same && tally->differ++ == 0)
    tally->first = "ray o=(" + std::to_string(ray.o.x) + "," + std::to_string(ray.o.y) + "," +
                   std::to_string(ray.o.z) + ") part1 hit=" + std::to_string(hw) +
                   " t=" + std::to_string(want.t) + ", sheared hit=" + std::to_string(hg) +
                   " t=" + std::to_string(got.t);
}

TEST(AccelTriangle, BitIdenticalToPart1OnMillionsOfRays) {
  Rng rng(1234);
  Tally tally;
  // Scales from tiny to huge, near and far from the origin.
  const float scales[] = {1e-3f, 1.0f, 1e3f};
  const float offsets[] = {0.0f, 10.0f, 1e5f};
  for (int i = 0; i < 1500000; ++i) {
    const float scale = scales[rng.next_u32() % 3], offset = offsets[rng.next_u32() % 3];
    const glm::vec3 centre = random_in_cube(rng, offset);
    glm::vec3 p[3];
    for (glm::vec3& q : p) q = centre + random_in_cube(rng, scale);
    const uint32_t kind = rng.next_u32() % 8;
    if (kind == 0) p[2] = p[1];                            // two equal corners
    if (kind == 1) p[2] = p[0] + 0.5f * (p[1] - p[0]);     // (nearly) collinear
    Ray ray;
    ray.o = centre + random_in_cube(rng, 4.0f * scale);
    // Aimed at a random point, a corner or an edge's midpoint: where neighbours tie.
    const float a = rng.next_float(), b = rng.next_float() * (1.0f - a);
    const uint32_t aim = rng.next_u32() % 4;
    const glm::vec3 target = aim == 0   ? p[rng.next_u32() % 3]
                             : aim == 1 ? 0.5f * (p[0] + p[1])
                                        : p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
    ray.d = target - ray.o;
    if (rng.next_u32() % 4 == 0) ray.d = glm::normalize(ray.d);
    const uint32_t dir = rng.next_u32() % 16;
    if (dir == 0) ray.d = square_to_uniform_sphere(rng.next_2d());  // mostly misses
    if (dir == 1) ray.d[rng.next_u32() % 3] = 0.0f;                 // a zero component
    if (dir == 2) ray.d[rng.next_u32() % 3] = -0.0f;                // a negative zero
    if (dir == 3) {                                                 // grazing: in the plane
      const glm::vec3 e = p[1] - p[0];
      ray.o = p[0] - e, ray.d = e;
    }
    if (dir == 4) ray.d = glm::vec3(0.0f);                           // no direction at all
    const uint32_t interval = rng.next_u32() % 8;
    if (interval == 0) ray.tmax = rng.next_float() * 2.0f;
    if (interval == 1) ray.tmin = rng.next_float();
    compare(ray, p[0], p[1], p[2], &tally);
    // The same ray with tmax at its own hit, and an ulp either side: where t·det rounding decides.
    TriangleHit h;
    if (intersect_triangle(ray, p[0], p[1], p[2], &h)) {
      for (float tmax : {h.t, next_float_down(h.t), next_float_up(h.t)}) {
        Ray r = ray;
        r.tmax = tmax;
        compare(r, p[0], p[1], p[2], &tally);
      }
    }
  }
  EXPECT_EQ(tally.differ, 0u) << tally.first;
  EXPECT_EQ(tally.filter_lost, 0u) << tally.first;
  EXPECT_EQ(tally.simd_differ, 0u) << tally.first;
  EXPECT_EQ(tally.eight_differ, 0u) << tally.first;
  EXPECT_EQ(tally.eight_hits, tally.simd_hits) << "the eight-lane test answers the same hits";
  // Most, not all: these rays aim at corners and edges, where an edge function is exactly 0.
  EXPECT_GT(tally.simd_hits, tally.hits / 2) << "the four-lane test should answer most hits itself";
  EXPECT_GT(tally.filtered, (tally.cases - tally.hits) / 2) << "the filter should reject most misses";
  EXPECT_GT(tally.hits, tally.cases / 5) << "too few hits to be a test";
  EXPECT_LT(tally.hits, tally.cases) << "no misses at all";
  std::printf("%zu cases, %zu hits, %zu differ; filter rejected %zu, wrongly %zu; four-lane test "
              "answered %zu hits, handed back %zu lanes, differed on %zu; eight-lane test (%s) "
              "differed on %zu\n",
              tally.cases, tally.hits, tally.differ, tally.filtered, tally.filter_lost,
              tally.simd_hits, tally.simd_retests, tally.simd_differ,
              PT_ACCEL_AVX ? "AVX" : "two four-lane tests", tally.eight_differ);
}

TEST(AccelTriangle, NonFiniteInputsAnswerAsPart1) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
  Tally tally;
  const glm::vec3 p0(-1, -1, 0), p1(1, -1, 0), p2(0, 1, 0);
  for (float bad : {inf, -inf, nan})
    for (int k = 0; k < 3; ++k) {
      Ray ray;
      ray.o = glm::vec3(0.1f, 0.2f, 1.0f);
      ray.d = glm::vec3(0, 0, -1);
      Ray r = ray;
      r.d[k] = bad;
      compare(r, p0, p1, p2, &tally);
      r = ray;
      r.o[k] = bad;
      compare(r, p0, p1, p2, &tally);
      glm::vec3 q = p1;
      q[k] = bad;
      compare(ray, p0, q, p2, &tally);
    }
  EXPECT_EQ(tally.differ, 0u) << tally.first;
  EXPECT_EQ(tally.filter_lost, 0u) << tally.first;
  EXPECT_EQ(tally.simd_differ, 0u) << tally.first;
  EXPECT_EQ(tally.eight_differ, 0u) << tally.first;
}

}  // namespace
}  // namespace pt
