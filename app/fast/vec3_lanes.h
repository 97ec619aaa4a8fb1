// Three-float vectors in the lanes of one SSE register, each operation the very one glm does
// component by component (so the same bits), for the paths every light sample, shadow ray and
// wide-tree hit takes in the instructor's build: glm's vec3 code runs one component at a time.
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#pragma once

#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

#include "app/fast/sse.h"
#ifdef __SSE4_1__
#include <smmintrin.h>
#endif
#ifdef __AVX__
#include <immintrin.h>
#endif

#if PT_SSE2
namespace pt::lanes {

/// x, y, z in lanes 0-2; lane 3 is 0 after a load and carries no meaning.
using V3 = __m128;

inline V3 load(const glm::vec3& a) {
#ifdef __SSE4_1__
  // x and y in one 8-byte load, z inserted from memory: two instructions where the element by
  // element set took three.
  const V3 xy = _mm_castsi128_ps(_mm_loadu_si64(&a.x));
  return _mm_insert_ps(xy, _mm_load_ss(&a.z), 0x20);
#else
  return _mm_setr_ps(a.x, a.y, a.z, 0.0f);
#endif
}
inline glm::vec3 to_vec3(V3 v) {
  alignas(16) float f[4];
  _mm_store_ps(f, v);
  return {f[0], f[1], f[2]};
}
inline V3 splat(float x) { return _mm_set1_ps(x); }
inline V3 add(V3 a, V3 b) { return _mm_add_ps(a, b); }
inline V3 sub(V3 a, V3 b) { return _mm_sub_ps(a, b); }
inline V3 mul(V3 a, V3 b) { return _mm_mul_ps(a, b); }
inline V3 div(V3 a, V3 b) { return _mm_div_ps(a, b); }
inline V3 neg(V3 a) { return _mm_xor_ps(a, _mm_set1_ps(-0.0f)); }
/// glm::dot: the products summed as (x + y) + z.
inline float dot(V3 a, V3 b) {
  const V3 p = _mm_mul_ps(a, b);
  const V3 y = _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1));
  const V3 z = _mm_movehl_ps(p, p);
  return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(p, y), z));
}
/// Lane by lane, a where mask (a comparison's: all bits or none) is set and b elsewhere: one blend
/// where the build has SSE4.1 (an AVX2 build does), three logic operations on SSE2.
inline V3 select(V3 mask, V3 a, V3 b) {
#ifdef __SSE4_1__
  return _mm_blendv_ps(b, a, mask);
#else
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
#endif
}
/// glm::abs: x >= 0 ? x : -x, lane by lane (so -0 stays -0, and a NaN changes sign, as there).
inline V3 glm_abs(V3 x) { return select(_mm_cmpge_ps(x, _mm_setzero_ps()), x, neg(x)); }
#ifdef __AVX__
/// glm_abs on eight lanes (two points, or one coordinate of eight).
inline __m256 glm_abs(__m256 x) {
  return _mm256_blendv_ps(_mm256_xor_ps(x, _mm256_set1_ps(-0.0f)), x,
                          _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_GE_OQ));
}
#endif
/// offset_ray_origin's last step (float_error.h), lane by lane and to the bit: v moved to the next
/// float up where `offset` > 0 and down where it is < 0, left where it is 0 or NaN. Up: +inf
/// stays, ±0 steps to the smallest denormal, anything else (NaN included) moves one unit in its
/// bits; down the mirror image. For four lanes (__m128) or eight (__m256, two points at once), in
/// GCC's vector operations, which give each width its own instructions: the two steps in one,
/// as the bits move down exactly where the step's direction and v's sign disagree.
template <class F>
[[gnu::always_inline]] inline F round_away(F v, F offset) {
  using I = decltype(v < v);  // the lanes' integer masks (all bits or none)
  const F zero{};
  const I up = offset > zero, down = offset < zero;
  const I bits = reinterpret_cast<I>(v);
  const I lower = up ^ (v > zero);  // NaN counts as below zero: up lowers, down raises its bits
  const I is_zero = v == zero;
  // ±0 counts as +0 going up and -0 going down, and from there both step up in the bits.
  const I from = is_zero ? (down & INT32_MIN) : bits;
  const I stepped = from + ((lower & ~is_zero) | 1);
  const I keep_infinity = ((bits & INT32_MAX) == 0x7f800000) & ~lower;  // +inf up, -inf down
  return reinterpret_cast<F>(((up | down) & ~keep_infinity) ? stepped : bits);
}
/// glm::cross: (a.y·b.z − b.y·a.z, a.z·b.x − b.z·a.x, a.x·b.y − b.x·a.y), the same products in
/// the same order.
inline V3 cross(V3 a, V3 b) {
  const V3 a_yzx = _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1));
  const V3 b_zxy = _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 1, 0, 2));
  const V3 b_yzx = _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 0, 2, 1));
  const V3 a_zxy = _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 1, 0, 2));
  return _mm_sub_ps(_mm_mul_ps(a_yzx, b_zxy), _mm_mul_ps(b_yzx, a_zxy));
}
/// Whether lanes 0-2 are all == 0 (glm's v == vec3(0)).
inline bool all_zero(V3 a) {
  return (_mm_movemask_ps(_mm_cmpeq_ps(a, _mm_setzero_ps())) & 7) == 7;
}

}  // namespace pt::lanes
#endif
