// spawn_ray_in_lanes and spawn_ray_to_in_lanes give their definitions' bits (framework's
// spawn_ray and spawn_ray_to), on every special value of the offset's last step.
// SOLUTION-ONLY FILE: not in the student handout, since it tests the instructor's build's speed.
#include "app/fast/lane_rays.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "framework/math/float_error.h"
#include "app/fast/vec3_lanes.h"
#include "framework/sampling/rng.h"
#ifdef __AVX2__
#include <immintrin.h>
#endif

namespace pt {
namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kMax = std::numeric_limits<float>::max();
const float kDenorm = std::numeric_limits<float>::denorm_min();

// Values where the steps to the next float have their special cases.
const std::vector<float> kSpecial = {0.0f, -0.0f, kDenorm, -kDenorm, 1.0f, -1.0f, kMax, -kMax,
                                     kInf, -kInf, kNaN, -kNaN, 1e-38f, -1e-38f, 3.5f, -2e10f};

#if PT_SSE2
// offset_ray_origin's step: up where the offset is positive, down where negative, none at zero or
// NaN; each lane of four, and of eight where the build has AVX2.
float step_definition(float v, float offset) {
  return offset > 0 ? next_float_up(v) : offset < 0 ? next_float_down(v) : v;
}

TEST(FastLaneRays, LaneRoundingAwayIsTheScalarStepBitForBit) {
  int lanes_checked = 0;
  for (float a : kSpecial)
    for (float b : kSpecial)
      for (float c : kSpecial) {
        const glm::vec3 v(a, b, c);
        // each value against each offset: the offsets run through kSpecial in another order
        const glm::vec3 offset(b, c, a);
        const __m128 got = lanes::round_away(lanes::load(v), lanes::load(offset));
        const glm::vec3 g = lanes::to_vec3(got);
        for (int k = 0; k < 3; ++k, ++lanes_checked)
          ASSERT_EQ(float_to_bits(g[k]), float_to_bits(step_definition(v[k], offset[k])))
              << v[k] << " by " << offset[k];
#ifdef __AVX2__
        const __m256 got8 = lanes::round_away(_mm256_set_m128(lanes::load(offset), lanes::load(v)),
                                              _mm256_set_m128(lanes::load(v), lanes::load(offset)));
        const glm::vec3 lo = lanes::to_vec3(_mm256_castps256_ps128(got8));
        const glm::vec3 hi = lanes::to_vec3(_mm256_extractf128_ps(got8, 1));
        for (int k = 0; k < 3; ++k) {
          ASSERT_EQ(float_to_bits(lo[k]), float_to_bits(step_definition(v[k], offset[k])));
          ASSERT_EQ(float_to_bits(hi[k]), float_to_bits(step_definition(offset[k], v[k])));
        }
#endif
      }
  EXPECT_EQ(lanes_checked, 3 * 16 * 16 * 16);
}
#endif

void expect_same_ray(const Ray& got, const Ray& want, int i) {
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(float_to_bits(got.o[k]), float_to_bits(want.o[k])) << "o[" << k << "], case " << i;
    ASSERT_EQ(float_to_bits(got.d[k]), float_to_bits(want.d[k])) << "d[" << k << "], case " << i;
  }
  ASSERT_EQ(float_to_bits(got.tmin), float_to_bits(want.tmin)) << "tmin, case " << i;
  ASSERT_EQ(float_to_bits(got.tmax), float_to_bits(want.tmax)) << "tmax, case " << i;
}

// Shading points and targets all around, at zero coordinates of either sign, huge and tiny, on
// top of each other, with and without a target surface: the shadow ray and the bounce ray are
// their definitions', to the bit.
TEST(FastLaneRays, ShadowAndBounceRaysAreTheirDefinitionBitForBit) {
  Rng rng(5, 9);
  auto random_vec = [&](float scale) {
    return scale * glm::vec3(rng.next_float() * 2 - 1, rng.next_float() * 2 - 1,
                             rng.next_float() * 2 - 1);
  };
  int nonempty = 0;
  for (int i = 0; i < 50000; ++i) {
    const float scale = i % 7 == 0 ? 1e5f : i % 5 == 0 ? 1e-5f : 3.0f;
    SurfaceHit hit;
    hit.p = random_vec(scale);
    hit.p_error = glm::abs(random_vec(scale * 1e-6f));
    hit.ng = glm::normalize(random_vec(1.0f) + glm::vec3(1e-3f));
    if (i % 3 == 0) hit.ng = glm::vec3(0, 0, i % 2 ? 1.0f : -1.0f);
    if (i % 4 == 0) hit.p[i % 3] = i % 8 ? 0.0f : -0.0f;
    glm::vec3 p = random_vec(scale);
    if (i % 13 == 0) p = hit.p;  // the target on the shading point: an empty interval
    const glm::vec3 p_error = i % 6 == 0 ? glm::vec3(0.0f) : glm::abs(random_vec(scale * 1e-6f));
    glm::vec3 n = i % 9 == 0 ? glm::vec3(0.0f) : glm::normalize(random_vec(1.0f) + glm::vec3(1e-3f));
    if (i % 10 == 0) n = glm::vec3(i % 20 ? -0.0f : 0.0f, 0.0f, 1.0f);
    const glm::vec3 d = p - hit.p;
    const float len = glm::length(d);
    const glm::vec3 w = len > 0.0f ? d / len : glm::vec3(0, 0, 1);
    const Ray got = spawn_ray_to_in_lanes(hit, w, p, p_error, n);
    expect_same_ray(got, spawn_ray_to(hit, w, p, p_error, n), i);
    nonempty += got.tmax > 0.0f;
    // and the bounce ray in the same direction
    expect_same_ray(spawn_ray_in_lanes(hit, w), spawn_ray(hit, w), i);
  }
  EXPECT_GT(nonempty, 40000) << "most cases should have something between the two points";
}

TEST(FastLaneRays, NonFiniteInputsGiveTheDefinitionsBits) {
  int i = 0;
  for (float a : kSpecial)
    for (float b : kSpecial) {
      SurfaceHit hit;
      hit.p = glm::vec3(a, 1.0f, b);
      hit.p_error = glm::vec3(1e-7f);
      hit.ng = glm::vec3(0.0f, 1.0f, 0.0f);
      const glm::vec3 p(b, 2.0f, a), n(0.0f, -1.0f, 0.0f), w(0.0f, 1.0f, 0.0f);
      const Ray got = i % 2 ? spawn_ray_to_in_lanes(hit, w, p, glm::vec3(1e-7f), n)
                            : spawn_ray_in_lanes(hit, w);
      const Ray want = i % 2 ? spawn_ray_to(hit, w, p, glm::vec3(1e-7f), n) : spawn_ray(hit, w);
      // NaN's payload is no answer; the rest is compared to the bit.
      for (int k = 0; k < 3; ++k) {
        if (std::isnan(want.o[k])) ASSERT_TRUE(std::isnan(got.o[k])) << i;
        else ASSERT_EQ(float_to_bits(got.o[k]), float_to_bits(want.o[k])) << i;
        if (std::isnan(want.d[k])) ASSERT_TRUE(std::isnan(got.d[k])) << i;
        else ASSERT_EQ(float_to_bits(got.d[k]), float_to_bits(want.d[k])) << i;
      }
      if (std::isnan(want.tmax)) ASSERT_TRUE(std::isnan(got.tmax)) << i;
      else ASSERT_EQ(float_to_bits(got.tmax), float_to_bits(want.tmax)) << i;
      ++i;
    }
}

}  // namespace
}  // namespace pt
