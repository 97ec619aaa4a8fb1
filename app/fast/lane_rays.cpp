// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#include "app/fast/lane_rays.h"

#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "app/fast/vec3_lanes.h"
#include "framework/math/float_error.h"
#ifdef __AVX2__
#include <immintrin.h>
#endif

namespace pt {

#if PT_SSE2
namespace {
using namespace lanes;

// offset_ray_origin (float_error.h) in three lanes, the same operations in the same order.
[[gnu::always_inline]] inline V3 offset_origin(V3 p, V3 p_error, V3 n, V3 w) {
  const float d = lanes::dot(glm_abs(n), p_error);
  V3 offset = mul(splat(d), n);
  if (lanes::dot(w, n) < 0) offset = neg(offset);
  return round_away(add(p, offset), offset);
}

#ifdef __AVX2__
// Two points in one register: the first in lanes 0-2, the second in lanes 4-6. (AVX2, not AVX:
// round_away's steps are integer operations on all eight lanes.)
using V3x2 = __m256;

inline V3x2 pair(V3 first, V3 second) { return _mm256_set_m128(second, first); }

// lanes::dot of each half, in every lane of that half: the products summed as (x + y) + z.
inline V3x2 dot_each(V3x2 a, V3x2 b) {
  const V3x2 p = _mm256_mul_ps(a, b);
  const V3x2 sum = _mm256_add_ps(_mm256_add_ps(p, _mm256_permute_ps(p, _MM_SHUFFLE(1, 1, 1, 1))),
                                 _mm256_permute_ps(p, _MM_SHUFFLE(2, 2, 2, 2)));
  return _mm256_permute_ps(sum, _MM_SHUFFLE(0, 0, 0, 0));
}

// offset_origin of each half at once: the same operations on the same values, so each half's
// bits are the ones offset_origin gives it (the flip of the offset is a sign flip either way).
[[gnu::always_inline]] inline V3x2 offset_origins(V3x2 p, V3x2 p_error, V3x2 n, V3x2 w) {
  const V3x2 zero = _mm256_setzero_ps(), sign = _mm256_set1_ps(-0.0f);
  V3x2 offset = _mm256_mul_ps(dot_each(glm_abs(n), p_error), n);
  const V3x2 flip = _mm256_cmp_ps(dot_each(w, n), zero, _CMP_LT_OQ);
  offset = _mm256_xor_ps(offset, _mm256_and_ps(flip, sign));
  return round_away(_mm256_add_ps(p, offset), offset);
}
#endif

// The ray (o, d, 0, tmax), written as the two 16-byte halves the ray queries read it by
// (traceable in the wide tree), so that each of their loads is forwarded from one store instead
// of waiting for several to reach the cache.
[[gnu::always_inline]] inline Ray make_ray(V3 o, V3 d, float tmax) {
  static_assert(sizeof(Ray) == 8 * sizeof(float), "a ray is o, d, tmin, tmax side by side");
  const V3 oz_dx = _mm_shuffle_ps(o, d, _MM_SHUFFLE(0, 0, 2, 2));
  const V3 lo = _mm_shuffle_ps(o, oz_dx, _MM_SHUFFLE(2, 0, 1, 0));  // o.x o.y o.z d.x
  const V3 hi = _mm_shuffle_ps(d, _mm_setr_ps(0.0f, tmax, 0.0f, 0.0f),
                               _MM_SHUFFLE(1, 0, 2, 1));  // d.y d.z tmin tmax
  alignas(16) float f[8];
  _mm_store_ps(f, lo);
  _mm_store_ps(f + 4, hi);
  Ray r;
  std::memcpy(&r, f, sizeof r);
  return r;
}

}  // namespace
#endif

Ray spawn_ray_in_lanes(const SurfaceHit& hit, const glm::vec3& w) {
#if PT_SSE2
  const V3 wv = load(w);
  return make_ray(offset_origin(load(hit.p), load(hit.p_error), load(hit.ng), wv), wv,
                  std::numeric_limits<float>::infinity());
#else
  return spawn_ray(hit, w);
#endif
}

Ray spawn_ray_to_in_lanes(const SurfaceHit& hit, const glm::vec3& w, const glm::vec3& p,
                          const glm::vec3& p_error, const glm::vec3& n) {
#if PT_SSE2
  const V3 wv = load(w);
#ifdef __AVX2__
  // Both ends offset at once, the shading point's in the low half, the target's in the high.
  const V3 nv = load(n);
  const V3x2 ends = offset_origins(pair(load(hit.p), load(p)), pair(load(hit.p_error), load(p_error)),
                                   pair(load(hit.ng), nv), pair(wv, neg(wv)));
  const V3 o = _mm256_castps256_ps128(ends);
  const V3 target = all_zero(nv) ? load(p) : _mm256_extractf128_ps(ends, 1);
#else
  const V3 o = offset_origin(load(hit.p), load(hit.p_error), load(hit.ng), wv);
  V3 target = load(p);
  if (n != glm::vec3(0.0f)) target = offset_origin(target, load(p_error), load(n), neg(wv));
#endif
  const V3 d = sub(target, o);
  const float len = std::sqrt(lanes::dot(d, d));
  const bool empty = !(len > 0.0f);
  const V3 dir = empty ? wv : div(d, splat(len));
  return make_ray(o, dir, empty ? 0.0f : len * (1.0f - gamma(4)));
#else
  return spawn_ray_to(hit, w, p, p_error, n);
#endif
}

}  // namespace pt
