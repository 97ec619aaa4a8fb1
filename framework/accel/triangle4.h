// Four triangles against one ray at once (SSE where the target has it): a filter in front of the
// sheared triangle test that throws out, with the very same float operations, the triangles that
// test would throw out on its first checks, so most triangles of a leaf cost a quarter of a test.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#pragma once

#include <cstdint>

#include "accel/box4.h"
#include "accel/sheared_triangle.h"

namespace pt {

/// Up to four triangles of a leaf, structure of arrays: corner[c][axis][lane]. A lane that holds
/// no triangle (a sphere's entry, or past the leaf's end) has NaN corners, which the filter never
/// rejects; the caller knows which lanes are real.
struct alignas(16) Triangle4 {
  static constexpr uint32_t kLanes = 4;
  float corner[3][3][4];
};

/// A sheared ray with its per-ray values in every lane.
struct ShearedRay4 {
#if PT_ACCEL_SSE
  __m128 o[3], sx, sy, sz, tmin;
#endif
  ShearedRay r;

  explicit ShearedRay4(const ShearedRay& sheared) : r(sheared) { broadcast(); }
  /// Prepares the ray in place: copying a freshly made ShearedRay in costs a stalled
  /// store-to-load forward per ray, a few percent of a traversal.
  explicit ShearedRay4(const Ray& ray) : r(ray) { broadcast(); }

 private:
  void broadcast() {
#if PT_ACCEL_SSE
    for (int a = 0; a < 3; ++a) o[a] = _mm_set1_ps(r.o[a]);
    sx = _mm_set1_ps(r.sx), sy = _mm_set1_ps(r.sy), sz = _mm_set1_ps(r.sz);
    tmin = _mm_set1_ps(r.tmin);
#endif
  }
};

/// The lanes (bit k for lane k) that intersect_sheared_triangle(ray, tmax, ...) may accept: every
/// other lane it would reject, by the same comparisons of bit-identical values (edge functions of
/// mixed signs, a zero determinant, t outside the interval). A lane with an edge function of
/// exactly 0 (which the exact test recomputes in double) or a NaN is always a candidate.
inline unsigned triangle4_candidates(const Triangle4& tri, const ShearedRay4& ray, float tmax) {
  if (ray.r.degenerate) return 0u;
#if PT_ACCEL_SSE
  const int kx = ray.r.kx, ky = ray.r.ky, kz = ray.r.kz;
  __m128 ax = _mm_sub_ps(_mm_load_ps(tri.corner[0][kx]), ray.o[kx]);
  __m128 ay = _mm_sub_ps(_mm_load_ps(tri.corner[0][ky]), ray.o[ky]);
  __m128 az = _mm_sub_ps(_mm_load_ps(tri.corner[0][kz]), ray.o[kz]);
  __m128 bx = _mm_sub_ps(_mm_load_ps(tri.corner[1][kx]), ray.o[kx]);
  __m128 by = _mm_sub_ps(_mm_load_ps(tri.corner[1][ky]), ray.o[ky]);
  __m128 bz = _mm_sub_ps(_mm_load_ps(tri.corner[1][kz]), ray.o[kz]);
  __m128 cx = _mm_sub_ps(_mm_load_ps(tri.corner[2][kx]), ray.o[kx]);
  __m128 cy = _mm_sub_ps(_mm_load_ps(tri.corner[2][ky]), ray.o[ky]);
  __m128 cz = _mm_sub_ps(_mm_load_ps(tri.corner[2][kz]), ray.o[kz]);
  ax = _mm_add_ps(ax, _mm_mul_ps(ray.sx, az)), ay = _mm_add_ps(ay, _mm_mul_ps(ray.sy, az));
  bx = _mm_add_ps(bx, _mm_mul_ps(ray.sx, bz)), by = _mm_add_ps(by, _mm_mul_ps(ray.sy, bz));
  cx = _mm_add_ps(cx, _mm_mul_ps(ray.sx, cz)), cy = _mm_add_ps(cy, _mm_mul_ps(ray.sy, cz));
  const __m128 e0 = _mm_sub_ps(_mm_mul_ps(bx, cy), _mm_mul_ps(by, cx));
  const __m128 e1 = _mm_sub_ps(_mm_mul_ps(cx, ay), _mm_mul_ps(cy, ax));
  const __m128 e2 = _mm_sub_ps(_mm_mul_ps(ax, by), _mm_mul_ps(ay, bx));
  const __m128 zero = _mm_setzero_ps();
  const __m128 any_zero = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(e0, zero), _mm_cmpeq_ps(e1, zero)),
                                    _mm_cmpeq_ps(e2, zero));
  const __m128 any_neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(e0, zero), _mm_cmplt_ps(e1, zero)),
                                   _mm_cmplt_ps(e2, zero));
  const __m128 any_pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(e0, zero), _mm_cmpgt_ps(e1, zero)),
                                   _mm_cmpgt_ps(e2, zero));
  const __m128 det = _mm_add_ps(_mm_add_ps(e0, e1), e2);
  const __m128 t_scaled = _mm_add_ps(
      _mm_add_ps(_mm_mul_ps(e0, _mm_mul_ps(az, ray.sz)), _mm_mul_ps(e1, _mm_mul_ps(bz, ray.sz))),
      _mm_mul_ps(e2, _mm_mul_ps(cz, ray.sz)));
  const __m128 lo = _mm_mul_ps(ray.tmin, det), hi = _mm_mul_ps(_mm_set1_ps(tmax), det);
  const __m128 positive = _mm_cmpgt_ps(det, zero);
  // det > 0: out when t_scaled <= tmin·det or >= tmax·det; det < 0 (or NaN): the mirror image.
  const __m128 out_pos = _mm_or_ps(_mm_cmple_ps(t_scaled, lo), _mm_cmpge_ps(t_scaled, hi));
  const __m128 out_neg = _mm_or_ps(_mm_cmpge_ps(t_scaled, lo), _mm_cmple_ps(t_scaled, hi));
  const __m128 out_t = _mm_or_ps(_mm_and_ps(positive, out_pos), _mm_andnot_ps(positive, out_neg));
  const __m128 reject =
      _mm_or_ps(_mm_and_ps(any_neg, any_pos), _mm_or_ps(_mm_cmpeq_ps(det, zero), out_t));
  // A zero edge function is recomputed in double by the exact test: leave that lane to it.
  return unsigned(_mm_movemask_ps(_mm_or_ps(_mm_andnot_ps(reject, _mm_cmpord_ps(det, det)), any_zero))) |
         unsigned(_mm_movemask_ps(_mm_cmpunord_ps(det, det)));
#else
  (void)tri, (void)tmax;
  return 0xFu;  // no SIMD: every lane goes to the exact test
#endif
}

}  // namespace pt
