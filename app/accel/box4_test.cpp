// The wide BVH's four-box slab test against Part 2's intersect_box, lane by lane: the same answer
// and bit-identical entry distances, on random, flat and plane-touching boxes.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "app/accel/box4.h"
#include "framework/math/float_error.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "parts/2-bvh/ray_box.h"

namespace pt {
namespace {

glm::vec3 random_in_cube(Rng& rng, float half) {
  return half * (2.0f * glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 1.0f);
}

/// A random box: sometimes flat along an axis, sometimes with the ray's origin on one of its
/// planes (where the slab distance is 0 · inf for a ray parallel to it).
Bounds3 random_box(Rng& rng, const glm::vec3& o) {
  Bounds3 b;
  b.grow(random_in_cube(rng, 4.0f));
  b.grow(random_in_cube(rng, 4.0f));
  const int axis = int(rng.next_u32() % 3);
  const uint32_t kind = rng.next_u32() % 6;
  if (kind == 0) b.hi[axis] = b.lo[axis];
  if (kind == 1 || kind == 2) {
    if (o[axis] < b.lo[axis]) b.lo[axis] = o[axis];
    else if (o[axis] > b.hi[axis]) b.hi[axis] = o[axis];
    else (kind == 1 ? b.lo : b.hi)[axis] = o[axis];
  }
  return b;
}

// The wide tree's entry check answers as is_traceable on rays made of every kind of float in every
// field: zeros of both signs, denormals, infinities, NaNs, the largest floats and random bits.
TEST(AccelBox4, TraceableIsIsTraceable) {
  const float inf = std::numeric_limits<float>::infinity();
  const float kinds[] = {0.0f, -0.0f, 1.0f, -2.5f, std::numeric_limits<float>::denorm_min(),
                         -std::numeric_limits<float>::max(), inf, -inf,
                         std::numeric_limits<float>::quiet_NaN(), bits_to_float(0xFF800001u)};
  constexpr int kKinds = int(sizeof(kinds) / sizeof(kinds[0]));
  Rng rng(9, 5);
  long traceable_rays = 0, rays = 0;
  for (int i = 0; i < 400000; ++i) {
    float f[8];
    for (float& x : f) {
      const uint32_t pick = rng.next_u32() % 16;
      // Mostly ordinary numbers, so that a ray is traceable about half the time.
      x = pick < kKinds && rng.next_u32() % 4 == 0 ? kinds[pick]
          : pick == 15                            ? bits_to_float(rng.next_u32())
                                                  : rng.next_float() * 4.0f - 2.0f;
    }
    if (i % 3 == 0) f[3] = f[4] = f[5] = (i % 2 ? 0.0f : -0.0f);  // a zero direction
    if (i % 5 == 0) f[3 + i % 3] = 0.0f;                          // one zero component
    Ray r;
    r.o = glm::vec3(f[0], f[1], f[2]);
    r.d = glm::vec3(f[3], f[4], f[5]);
    r.tmin = f[6];
    r.tmax = i % 7 == 0 ? inf : f[7];
    ASSERT_EQ(traceable(r), is_traceable(r)) << "ray " << i;
    traceable_rays += is_traceable(r);
    ++rays;
  }
  EXPECT_GT(traceable_rays, rays / 10);
  EXPECT_LT(traceable_rays, rays - rays / 10);
}

TEST(AccelBox4, EachLaneAnswersAsPart2) {
  Rng rng(77);
  size_t lanes = 0, hits = 0, differ = 0, more_conservative = 0;
  std::string first;
  for (int i = 0; i < 400000; ++i) {
    Ray ray;
    ray.o = random_in_cube(rng, 5.0f);
    ray.d = square_to_uniform_sphere(rng.next_2d());
    const uint32_t kind = rng.next_u32() % 6;
    if (kind == 0) ray.d[rng.next_u32() % 3] = 0.0f;
    if (kind == 1) ray.d[rng.next_u32() % 3] = -0.0f;
    if (kind == 2) ray.tmin = rng.next_float() * 3.0f;
    const float tmax = kind == 3 ? rng.next_float() * 4.0f : std::numeric_limits<float>::infinity();
    Box4 box4;
    Bounds3 boxes[4];
    for (int k = 0; k < 4; ++k) {
      boxes[k] = random_box(rng, ray.o);
      for (int a = 0; a < 3; ++a) {
        box4.bounds[a][k] = boxes[k].lo[a];
        box4.bounds[3 + a][k] = boxes[k].hi[a];
      }
    }
    alignas(16) float t4[4];
    const unsigned mask = intersect_box4(box4, Box4Ray(ray), tmax, t4);
    const BoxRay box_ray(ray);
    for (int k = 0; k < 4; ++k) {
      float t;
      const bool want = intersect_box(boxes[k], box_ray, tmax, &t);
      const bool got = (mask >> k) & 1u;
      ++lanes;
      hits += want;
      // Part 2 orders a slab's two distances by value, so for a -0 component with the origin on
      // a plane (0 · -inf = NaN beside -inf) it can drop a box the ray runs along; ordering by
      // the direction's sign keeps it. That is the one way the lanes may differ: more hits.
      const bool negative_zero = (std::signbit(ray.d.x) && ray.d.x == 0.0f) ||
                                 (std::signbit(ray.d.y) && ray.d.y == 0.0f) ||
                                 (std::signbit(ray.d.z) && ray.d.z == 0.0f);
      if (got && !want && negative_zero) {
        ++more_conservative;
        continue;
      }
      if (got != want || (want && float_to_bits(t) != float_to_bits(t4[k]))) {
        if (differ++ == 0)
          first = "lane " + std::to_string(k) + ": part 2 " + std::to_string(want) + " t=" +
                  std::to_string(t) + ", box4 " + std::to_string(got) + " t=" + std::to_string(t4[k]);
      }
    }
  }
  EXPECT_EQ(differ, 0u) << first;
  EXPECT_GT(hits, lanes / 20) << "too few hits to be a test";
  EXPECT_LT(hits, lanes) << "no misses at all";
  std::printf("%zu lanes, %zu hits, %zu kept only by box4 (-0 directions)\n", lanes, hits,
              more_conservative);
}

TEST(AccelBox4, EmptySlotIsNeverMet) {
  Rng rng(3);
  Box4 box4;
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a) {
      box4.bounds[a][k] = std::numeric_limits<float>::infinity();
      box4.bounds[3 + a][k] = -std::numeric_limits<float>::infinity();
    }
  for (int i = 0; i < 10000; ++i) {
    Ray ray;
    ray.o = random_in_cube(rng, 5.0f);
    ray.d = square_to_uniform_sphere(rng.next_2d());
    if (i % 3 == 0) ray.d[i % 2] = (i % 4 == 0) ? 0.0f : -0.0f;
    alignas(16) float t4[4];
    ASSERT_EQ(intersect_box4(box4, Box4Ray(ray), std::numeric_limits<float>::infinity(), t4), 0u);
  }
}

// The node test of two Box4 at once (eight AVX lanes where the build has them) is the four-box
// test on each, bit for bit: the same lanes met, the same entry distances.
TEST(FrameworkAccelBox4, EightLanesAnswerAsTwoFourLaneTests) {
  Rng rng(19);
  size_t hits = 0, lanes = 0;
  for (int i = 0; i < 200000; ++i) {
    Ray ray;
    ray.o = random_in_cube(rng, 5.0f);
    ray.d = square_to_uniform_sphere(rng.next_2d());
    const uint32_t kind = rng.next_u32() % 5;
    if (kind == 0) ray.d[rng.next_u32() % 3] = 0.0f;
    if (kind == 1) ray.d[rng.next_u32() % 3] = -0.0f;
    if (kind == 2) ray.tmin = rng.next_float() * 3.0f;
    const float tmax = kind == 3 ? rng.next_float() * 4.0f : std::numeric_limits<float>::infinity();
    alignas(16) Box4 boxes[2];
    for (int k = 0; k < 8; ++k) {
      const Bounds3 b = (k == 5 && kind == 4) ? Bounds3{} : random_box(rng, ray.o);  // an empty slot
      for (int a = 0; a < 3; ++a) {
        boxes[k / 4].bounds[a][k % 4] = b.lo[a];
        boxes[k / 4].bounds[3 + a][k % 4] = b.hi[a];
      }
    }
    const Box4Ray box_ray(ray);
    alignas(32) float t8[8];
    alignas(16) float t4[8];
    const unsigned mask8 = intersect_box8(boxes, box_ray, tmax, t8);
    const unsigned mask4 = intersect_box4(boxes[0], box_ray, tmax, t4) |
                           intersect_box4(boxes[1], box_ray, tmax, t4 + 4) << 4;
    ASSERT_EQ(mask8, mask4) << "ray " << i;
    for (int k = 0; k < 8; ++k) {
      ++lanes;
      if (!(mask4 >> k & 1u)) continue;
      ++hits;
      ASSERT_EQ(float_to_bits(t8[k]), float_to_bits(t4[k])) << "ray " << i << " lane " << k;
    }
  }
  EXPECT_GT(hits, lanes / 20) << "too few hits to be a test";
  std::printf("intersect_box8: %s, %zu of %zu lanes met\n", PT_ACCEL_AVX ? "AVX" : "two SSE tests",
              hits, lanes);
}

}  // namespace
}  // namespace pt
