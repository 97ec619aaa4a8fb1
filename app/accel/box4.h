// Four boxes against one ray at once (SSE where the target has it): the wide BVH's slab test,
// conservative in the same way as Part 2's intersect_box.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#pragma once

#include <cmath>
#include <cstdint>

#include "framework/math/float_error.h"
#include "framework/math/ray.h"
#include "app/fast/sse.h"

// Eight lanes at once where the build targets AVX (PT_ISA in the top CMakeLists): the same
// operations on twice the lanes, so every answer is the four-lane one.
#if PT_SSE2 && defined(__AVX__)
#define PT_ACCEL_AVX 1
#include <immintrin.h>
#else
#define PT_ACCEL_AVX 0
#endif

namespace pt {

/// Four axis-aligned boxes, structure of arrays: bounds[0..2] are the lower x, y, z of the four
/// boxes, bounds[3..5] the upper ones, so one load brings the same plane of all four.
struct alignas(16) Box4 {
  float bounds[6][4];
};

/// Which of a box's six planes (Box4::bounds rows) a ray meets first and last along each axis.
struct BoxPlanes {
  int near_plane[3], far_plane[3];
};

/// The planes a ray meets first and last when its direction lies in `octant`: bit a set when the
/// direction is negative along axis a (a -0 counts as negative, as its reciprocal is -inf).
constexpr BoxPlanes box_planes(int octant) {
  BoxPlanes p{};
  for (int a = 0; a < 3; ++a) {
    const bool negative = (octant >> a & 1) != 0;
    p.near_plane[a] = negative ? 3 + a : a;
    p.far_plane[a] = negative ? a : 3 + a;
  }
  return p;
}

/// The planes of each of the eight octants, made once: a ray picks its row by the sign bits of
/// its reciprocal direction (one movemask) instead of choosing six indices axis by axis, which
/// was a third of a shadow ray's set-up in a small scene.
inline constexpr BoxPlanes kBoxPlanes[8] = {box_planes(0), box_planes(1), box_planes(2),
                                            box_planes(3), box_planes(4), box_planes(5),
                                            box_planes(6), box_planes(7)};

/// A ray prepared for Box4 tests: its origin and reciprocal direction in every lane, and per axis
/// which of a box's planes it meets first (chosen by the direction's sign, so no swap is needed
/// and a ray with a -0 component still treats the slab it runs along as unbounded).
struct Box4Ray {
#if PT_ACCEL_AVX
  __m256 o8[3], inv_d8[3];
  // The four-lane test reads the lower halves of the eight-lane values: no second copy to make.
  __m128 o(int a) const { return _mm256_castps256_ps128(o8[a]); }
  __m128 inv_d(int a) const { return _mm256_castps256_ps128(inv_d8[a]); }
#elif PT_SSE2
  __m128 o4[3], inv_d4[3];
  __m128 o(int a) const { return o4[a]; }
  __m128 inv_d(int a) const { return inv_d4[a]; }
#else
  float o4[3][4], inv_d4[3][4];
  float o(int a, int k) const { return o4[a][k]; }
  float inv_d(int a, int k) const { return inv_d4[a][k]; }
#endif
  /// The direction's octant: bit a set when it is negative along axis a (-0 included), as
  /// box_planes and a wide node's visiting orders take it.
  int octant = 0;
  const BoxPlanes* planes;  ///< kBoxPlanes[octant]
  float tmin = 0.0f;

  explicit Box4Ray(const Ray& ray) : tmin(ray.tmin) {
#if PT_SSE2
    // The three reciprocals in one division of four lanes (each lane rounded as a scalar
    // division would be): three divisions in a row were on every ray's way to its first box.
    alignas(16) float inverse[4];
    const __m128 inverse4 =
        _mm_div_ps(_mm_set1_ps(1.0f), _mm_setr_ps(ray.d.x, ray.d.y, ray.d.z, 1.0f));
    _mm_store_ps(inverse, inverse4);
    // A reciprocal keeps its direction's sign (1/-0 is -inf); lane 3 (1/1) is positive.
    octant = _mm_movemask_ps(inverse4) & 7;
#else
    octant = int(std::signbit(ray.d.x)) | int(std::signbit(ray.d.y)) << 1 |
             int(std::signbit(ray.d.z)) << 2;
#endif
    planes = &kBoxPlanes[octant];
    for (int a = 0; a < 3; ++a) {
#if PT_SSE2
      const float inv = inverse[a];
#else
      const float inv = 1.0f / ray.d[a];
#endif
#if PT_ACCEL_AVX
      o8[a] = _mm256_set1_ps(ray.o[a]);
      inv_d8[a] = _mm256_set1_ps(inv);
#elif PT_SSE2
      o4[a] = _mm_set1_ps(ray.o[a]);
      inv_d4[a] = _mm_set1_ps(inv);
#else
      for (int k = 0; k < 4; ++k) o4[a][k] = ray.o[a], inv_d4[a][k] = inv;
#endif
    }
  }
};

/// is_traceable(ray) (framework/math/ray.h), the same answer for every ray, from two loads of its
/// eight floats: a finite origin and direction (no exponent of all ones), a direction that is
/// not zero, and no NaN in the interval. Every query of the wide tree starts here, and the scalar
/// form's eight tests and branches were a tenth of a shadow ray in a small scene.
inline bool traceable(const Ray& ray) {
#if PT_ACCEL_AVX
  // All eight in one register (o.x o.y o.z d.x d.y d.z tmin tmax): one test of each kind. Loaded
  // as the two 16-byte halves a spawned ray is stored as (spawn_ray.cpp), so each half is
  // forwarded from its store: a 32-byte load across the two waited for both to reach the cache,
  // which cost the shadow ray more than the test saves wherever the spawn was inlined nearby.
  static_assert(sizeof(Ray) == 8 * sizeof(float), "a ray is o, d, tmin, tmax side by side");
  const __m256 v = _mm256_set_m128(_mm_loadu_ps(&ray.o.x + 4), _mm_loadu_ps(&ray.o.x));
  // |x| < inf fails for an infinity and for NaN: the finite test of o and d.
  const __m256 magnitude = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), v);
  const unsigned not_finite = unsigned(
      _mm256_movemask_ps(_mm256_cmp_ps(magnitude, _mm256_set1_ps(INFINITY), _CMP_NLT_UQ)));
  const unsigned nan = unsigned(_mm256_movemask_ps(_mm256_cmp_ps(v, v, _CMP_UNORD_Q)));
  const unsigned nonzero =
      unsigned(_mm256_movemask_ps(_mm256_cmp_ps(v, _mm256_setzero_ps(), _CMP_NEQ_OQ)));
  return ((not_finite & 0x3fu) | (nan & 0xc0u)) == 0 && (nonzero & 0x38u) != 0;
#elif PT_SSE2
  static_assert(sizeof(Ray) == 8 * sizeof(float), "a ray is o, d, tmin, tmax side by side");
  const float* f = &ray.o.x;
  const __m128 a = _mm_loadu_ps(f);      // o.x o.y o.z d.x
  const __m128 b = _mm_loadu_ps(f + 4);  // d.y d.z tmin tmax
  const __m128i exponent = _mm_set1_epi32(0x7f800000);
  auto not_finite = [&](__m128 v) {
    const __m128i e = _mm_and_si128(_mm_castps_si128(v), exponent);
    return unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(e, exponent))));
  };
  const __m128 zero = _mm_setzero_ps();
  const unsigned bad = not_finite(a) | (not_finite(b) & 3u) |
                       (unsigned(_mm_movemask_ps(_mm_cmpunord_ps(b, b))) & 12u);
  const unsigned direction = (unsigned(_mm_movemask_ps(_mm_cmpneq_ps(a, zero))) & 8u) |
                             (unsigned(_mm_movemask_ps(_mm_cmpneq_ps(b, zero))) & 3u);
  return bad == 0 && direction != 0;
#else
  return is_traceable(ray);
#endif
}

/// Which of the four boxes the ray meets at some distance in [ray.tmin, tmax]: bit k of the result
/// for box k, and t_entry[k] where it enters (clamped to tmin). The same test as Part 2's
/// intersect_box, lane by lane: each plane distance within γ(3) of exact, the near distance
/// moved down and the far one up by 2·γ(3) (scaling the largest near distance is scaling each,
/// since the scaling is monotone), a NaN distance (0 · inf) narrowing nothing. An empty box
/// (lo = +inf, hi = -inf) is never met.
inline unsigned intersect_box4(const Box4& box, const Box4Ray& ray, float tmax, float t_entry[4]) {
  constexpr float kFarScale = 1.0f + 2.0f * gamma(3);
  constexpr float kNearScale = 1.0f - 2.0f * gamma(3);
#if PT_SSE2
  // _mm_max_ps(x, acc) returns acc when x is NaN: a slab the ray runs inside of narrows nothing.
  __m128 tn = _mm_set1_ps(-INFINITY), tf = _mm_set1_ps(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const __m128 near_planes = _mm_load_ps(box.bounds[ray.planes->near_plane[a]]);
    const __m128 far_planes = _mm_load_ps(box.bounds[ray.planes->far_plane[a]]);
    const __m128 n = _mm_mul_ps(_mm_sub_ps(near_planes, ray.o(a)), ray.inv_d(a));
    const __m128 f = _mm_mul_ps(_mm_sub_ps(far_planes, ray.o(a)), ray.inv_d(a));
    tn = _mm_max_ps(n, tn);
    tf = _mm_min_ps(f, tf);
  }
  // Down for the near distance and up for the far one, whatever their sign.
  tn = _mm_min_ps(_mm_mul_ps(tn, _mm_set1_ps(kNearScale)), _mm_mul_ps(tn, _mm_set1_ps(kFarScale)));
  tf = _mm_max_ps(_mm_mul_ps(tf, _mm_set1_ps(kFarScale)), _mm_mul_ps(tf, _mm_set1_ps(kNearScale)));
  const __m128 t0 = _mm_max_ps(tn, _mm_set1_ps(ray.tmin));
  const __m128 t1 = _mm_min_ps(tf, _mm_set1_ps(tmax));
  _mm_storeu_ps(t_entry, t0);
  return unsigned(_mm_movemask_ps(_mm_cmple_ps(t0, t1)));
#else
  unsigned mask = 0;
  for (int k = 0; k < 4; ++k) {
    float tn = -INFINITY, tf = INFINITY;
    for (int a = 0; a < 3; ++a) {
      const float n = (box.bounds[ray.planes->near_plane[a]][k] - ray.o(a, k)) * ray.inv_d(a, k);
      const float f = (box.bounds[ray.planes->far_plane[a]][k] - ray.o(a, k)) * ray.inv_d(a, k);
      tn = n > tn ? n : tn;
      tf = f < tf ? f : tf;
    }
    tn = std::fmin(tn * kNearScale, tn * kFarScale);
    tf = std::fmax(tf * kFarScale, tf * kNearScale);
    const float t0 = tn > ray.tmin ? tn : ray.tmin;
    const float t1 = tf < tmax ? tf : tmax;
    t_entry[k] = t0;
    mask |= unsigned(t0 <= t1) << k;
  }
  return mask;
#endif
}

#if PT_ACCEL_AVX
/// Plane k of Box4::bounds of the eight boxes boxes[0] and boxes[1], one a lane.
inline __m256 box_planes8(const Box4 boxes[2], int k) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(boxes[0].bounds[k])),
                              _mm_load_ps(boxes[1].bounds[k]), 1);
}

/// Widens the slab interval [*tn, *tf] of eight lanes by its rounding error (Ize 2013). Every
/// eight-lane form of the box test (one ray and eight boxes, eight rays and one box, a packet's
/// bounds) ends with these operations, so each lane answers to the bit what intersect_box4 does.
inline void widen_slab_interval8(__m256* tn, __m256* tf) {
  constexpr float kFarScale = 1.0f + 2.0f * gamma(3);
  constexpr float kNearScale = 1.0f - 2.0f * gamma(3);
  *tn = _mm256_min_ps(_mm256_mul_ps(*tn, _mm256_set1_ps(kNearScale)),
                      _mm256_mul_ps(*tn, _mm256_set1_ps(kFarScale)));
  *tf = _mm256_max_ps(_mm256_mul_ps(*tf, _mm256_set1_ps(kFarScale)),
                      _mm256_mul_ps(*tf, _mm256_set1_ps(kNearScale)));
}
#endif

/// intersect_box4 on two Box4 at once: bit k of the result and t_entry[k] for box k % 4 of
/// boxes[k / 4]. With AVX one eight-lane test of the very same operations, lane by lane.
inline unsigned intersect_box8(const Box4 boxes[2], const Box4Ray& ray, float tmax,
                               float t_entry[8]) {
#if PT_ACCEL_AVX
  // _mm256_max_ps, like _mm_max_ps, returns its second operand when the first is NaN.
  __m256 tn = _mm256_set1_ps(-INFINITY), tf = _mm256_set1_ps(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const __m256 near_planes = box_planes8(boxes, ray.planes->near_plane[a]);
    const __m256 far_planes = box_planes8(boxes, ray.planes->far_plane[a]);
    const __m256 n = _mm256_mul_ps(_mm256_sub_ps(near_planes, ray.o8[a]), ray.inv_d8[a]);
    const __m256 f = _mm256_mul_ps(_mm256_sub_ps(far_planes, ray.o8[a]), ray.inv_d8[a]);
    tn = _mm256_max_ps(n, tn);
    tf = _mm256_min_ps(f, tf);
  }
  widen_slab_interval8(&tn, &tf);
  const __m256 t0 = _mm256_max_ps(tn, _mm256_set1_ps(ray.tmin));
  const __m256 t1 = _mm256_min_ps(tf, _mm256_set1_ps(tmax));
  _mm256_storeu_ps(t_entry, t0);
  return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OS)));
#else
  return intersect_box4(boxes[0], ray, tmax, t_entry) |
         intersect_box4(boxes[1], ray, tmax, t_entry + 4) << 4;
#endif
}

}  // namespace pt
