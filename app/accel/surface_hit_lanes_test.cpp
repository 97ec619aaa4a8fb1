// triangle_surface_hit_in_lanes: the SIMD path every wide-tree hit takes gives its definition's
// (pipeline/1-raygen's triangle_surface_hit) bits.
// SOLUTION-ONLY FILE: not in the student handout, since it tests the instructor's build's speed.
#include "app/accel/surface_hit_lanes.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "framework/math/float_error.h"
#include "framework/sampling/rng.h"

namespace pt {
namespace {

void expect_same_bits(const glm::vec3& got, const glm::vec3& want, const char* what, int i) {
  for (int k = 0; k < 3; ++k)
    ASSERT_EQ(float_to_bits(got[k]), float_to_bits(want[k])) << what << "[" << k << "], case " << i;
}

// Triangles of every size and place (zero coordinates of either sign, huge and tiny, slivers,
// corners that coincide, NaN and infinite corners), with and without vertex normals (some of
// them cancelling out, some pointing against the winding), at barycentrics inside and outside:
// every field of the SurfaceHit, and whether there is one, is the definition's.
TEST(AccelSurfaceHit, TriangleSurfaceHitInLanesIsItsDefinitionBitForBit) {
  Rng rng(21, 3);
  auto coordinate = [&](int i) {
    float v = rng.next_float() * 2.0f - 1.0f;
    switch (rng.next_u32() % 40) {
      case 0: return i % 2 ? 0.0f : -0.0f;
      case 1: return v * 1e30f;
      case 2: return v * 1e-30f;
      case 3: return v * 1e4f;
      default: return v;
    }
  };
  auto vec = [&](int i) { return glm::vec3(coordinate(i), coordinate(i + 1), coordinate(i + 2)); };
  const float special[] = {std::numeric_limits<float>::infinity(),
                           std::numeric_limits<float>::quiet_NaN(), 0.0f, -0.0f};
  Scene with_normals, without_normals;
  for (Scene* s : {&with_normals, &without_normals}) {
    s->materials.resize(3);
    s->triangles = {Triangle{{0, 1, 2}, 2}};
    s->positions.resize(3);
  }
  with_normals.normals.resize(3);
  int hits = 0, refused = 0;
  for (int i = 0; i < 60000; ++i) {
    glm::vec3 p[3] = {vec(i), vec(i + 3), vec(i + 5)};
    if (i % 9 == 0) p[1] = p[0];                                  // two corners in one place
    if (i % 13 == 0) p[2] = p[0] + 0.5f * (p[1] - p[0]);          // collinear, or nearly
    if (i % 17 == 0) p[i % 3][(i / 17) % 3] = special[(i / 51) % 4];
    for (int k = 0; k < 3; ++k) {
      glm::vec3 n = vec(i + 7 * k);
      if (i % 11 == 0) n = glm::vec3(0.0f);                       // no normal to interpolate
      if (i % 19 == 0 && k == 1) n = -with_normals.normals[0];    // corners that cancel out
      with_normals.normals[k] = n;
    }
    const float b1 = rng.next_float() * 1.2f - 0.1f, b2 = rng.next_float() * 1.2f - 0.1f;
    const TriangleHit th{rng.next_float() * 10.0f, 1.0f - b1 - b2, b1, b2};
    const uint32_t vertex[3] = {0, 1, 2};
    for (Scene* s : {&with_normals, &without_normals}) {
      SurfaceHit got, want;
      const bool a = triangle_surface_hit_in_lanes(*s, 0, th, p[0], p[1], p[2], vertex, &got);
      const bool b = triangle_surface_hit(*s, 0, th, p[0], p[1], p[2], vertex, &want);
      ASSERT_EQ(a, b) << "case " << i;
      if (!a) {
        ++refused;
        continue;
      }
      ++hits;
      ASSERT_EQ(float_to_bits(got.t), float_to_bits(want.t)) << "t, case " << i;
      expect_same_bits(got.p, want.p, "p", i);
      expect_same_bits(got.p_error, want.p_error, "p_error", i);
      expect_same_bits(got.ng, want.ng, "ng", i);
      expect_same_bits(got.n, want.n, "n", i);
      ASSERT_EQ(got.primitive, want.primitive);
      ASSERT_EQ(got.material, want.material);
    }
  }
  EXPECT_GT(hits, 60000) << "most triangles make a hit";
  EXPECT_GT(refused, 1000) << "degenerate ones are refused: not a test of them otherwise";
}

}  // namespace
}  // namespace pt
