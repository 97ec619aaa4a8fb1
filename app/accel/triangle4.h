// Four triangles against one ray at once (SSE where the target has it): the sheared triangle test
// in four lanes with the very same float operations, so most triangles of a leaf cost a quarter of
// a test and a hit comes with Part 1's t and barycentrics; only a lane with an edge function of
// exactly 0 (or a non-finite value) is handed back to the scalar test.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#pragma once

#include <cmath>
#include <cstdint>

#include "app/accel/box4.h"
#include "app/accel/sheared_triangle.h"

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
  /// Whether triangle4_intersect may finish Part 1's test in SIMD lanes: with a shear of finite
  /// values, its maxima see no NaN (where _mm_max_ps and std::max part ways).
  bool finite_shear = false;

  explicit ShearedRay4(const ShearedRay& sheared) : r(sheared) { broadcast(); }
  /// Prepares the ray in place: copying a freshly made ShearedRay in costs a stalled
  /// store-to-load forward per ray, a few percent of a traversal.
  explicit ShearedRay4(const Ray& ray) : r(ray) { broadcast(); }

 private:
  void broadcast() {
    finite_shear = std::isfinite(r.sx) && std::isfinite(r.sy) && std::isfinite(r.sz);
#if PT_ACCEL_SSE
    for (int a = 0; a < 3; ++a) o[a] = _mm_set1_ps(r.o[a]);
    sx = _mm_set1_ps(r.sx), sy = _mm_set1_ps(r.sy), sz = _mm_set1_ps(r.sz);
    tmin = _mm_set1_ps(r.tmin);
#endif
  }
};

#if PT_ACCEL_SSE
namespace triangle4_detail {

/// The first steps of intersect_sheared_triangle in four lanes, with its very operations: the
/// corners relative to the origin and sheared, the edge functions, their sum and the scaled t.
struct Edges {
  __m128 ax, ay, az, bx, by, bz, cx, cy, cz;  ///< sheared corners, z scaled by sz
  __m128 e0, e1, e2, det, t_scaled;
  __m128 any_zero;  ///< an edge function of exactly 0, which the scalar test redoes in double
  __m128 reject;    ///< what the scalar test rejects, by the same comparisons (valid where no zero)
};

inline Edges edges(const Triangle4& tri, const ShearedRay4& ray, float tmax) {
  Edges g;
  const int kx = ray.r.kx, ky = ray.r.ky, kz = ray.r.kz;
  g.ax = _mm_sub_ps(_mm_load_ps(tri.corner[0][kx]), ray.o[kx]);
  g.ay = _mm_sub_ps(_mm_load_ps(tri.corner[0][ky]), ray.o[ky]);
  g.az = _mm_sub_ps(_mm_load_ps(tri.corner[0][kz]), ray.o[kz]);
  g.bx = _mm_sub_ps(_mm_load_ps(tri.corner[1][kx]), ray.o[kx]);
  g.by = _mm_sub_ps(_mm_load_ps(tri.corner[1][ky]), ray.o[ky]);
  g.bz = _mm_sub_ps(_mm_load_ps(tri.corner[1][kz]), ray.o[kz]);
  g.cx = _mm_sub_ps(_mm_load_ps(tri.corner[2][kx]), ray.o[kx]);
  g.cy = _mm_sub_ps(_mm_load_ps(tri.corner[2][ky]), ray.o[ky]);
  g.cz = _mm_sub_ps(_mm_load_ps(tri.corner[2][kz]), ray.o[kz]);
  g.ax = _mm_add_ps(g.ax, _mm_mul_ps(ray.sx, g.az)), g.ay = _mm_add_ps(g.ay, _mm_mul_ps(ray.sy, g.az));
  g.bx = _mm_add_ps(g.bx, _mm_mul_ps(ray.sx, g.bz)), g.by = _mm_add_ps(g.by, _mm_mul_ps(ray.sy, g.bz));
  g.cx = _mm_add_ps(g.cx, _mm_mul_ps(ray.sx, g.cz)), g.cy = _mm_add_ps(g.cy, _mm_mul_ps(ray.sy, g.cz));
  g.e0 = _mm_sub_ps(_mm_mul_ps(g.bx, g.cy), _mm_mul_ps(g.by, g.cx));
  g.e1 = _mm_sub_ps(_mm_mul_ps(g.cx, g.ay), _mm_mul_ps(g.cy, g.ax));
  g.e2 = _mm_sub_ps(_mm_mul_ps(g.ax, g.by), _mm_mul_ps(g.ay, g.bx));
  const __m128 zero = _mm_setzero_ps();
  g.any_zero = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(g.e0, zero), _mm_cmpeq_ps(g.e1, zero)),
                         _mm_cmpeq_ps(g.e2, zero));
  const __m128 any_neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(g.e0, zero), _mm_cmplt_ps(g.e1, zero)),
                                   _mm_cmplt_ps(g.e2, zero));
  const __m128 any_pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(g.e0, zero), _mm_cmpgt_ps(g.e1, zero)),
                                   _mm_cmpgt_ps(g.e2, zero));
  g.det = _mm_add_ps(_mm_add_ps(g.e0, g.e1), g.e2);
  g.az = _mm_mul_ps(g.az, ray.sz), g.bz = _mm_mul_ps(g.bz, ray.sz), g.cz = _mm_mul_ps(g.cz, ray.sz);
  g.t_scaled = _mm_add_ps(_mm_add_ps(_mm_mul_ps(g.e0, g.az), _mm_mul_ps(g.e1, g.bz)),
                          _mm_mul_ps(g.e2, g.cz));
  const __m128 lo = _mm_mul_ps(ray.tmin, g.det), hi = _mm_mul_ps(_mm_set1_ps(tmax), g.det);
  const __m128 positive = _mm_cmpgt_ps(g.det, zero);
  // det > 0: out when t_scaled <= tmin·det or >= tmax·det; det < 0 (or NaN): the mirror image.
  const __m128 out_pos = _mm_or_ps(_mm_cmple_ps(g.t_scaled, lo), _mm_cmpge_ps(g.t_scaled, hi));
  const __m128 out_neg = _mm_or_ps(_mm_cmpge_ps(g.t_scaled, lo), _mm_cmple_ps(g.t_scaled, hi));
  const __m128 out_t = _mm_or_ps(_mm_and_ps(positive, out_pos), _mm_andnot_ps(positive, out_neg));
  g.reject = _mm_or_ps(_mm_and_ps(any_neg, any_pos), _mm_or_ps(_mm_cmpeq_ps(g.det, zero), out_t));
  return g;
}

inline __m128 abs4(__m128 v) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), v); }
/// std::max({a, b, c}) for values that are not NaN.
inline __m128 max3(__m128 a, __m128 b, __m128 c) { return _mm_max_ps(_mm_max_ps(a, b), c); }

}  // namespace triangle4_detail
#endif

/// The lanes (bit k for lane k) that intersect_sheared_triangle(ray, tmax, ...) may accept: every
/// other lane it would reject, by the same comparisons of bit-identical values (edge functions of
/// mixed signs, a zero determinant, t outside the interval). A lane with an edge function of
/// exactly 0 (which the exact test recomputes in double) or a NaN is always a candidate.
inline unsigned triangle4_candidates(const Triangle4& tri, const ShearedRay4& ray, float tmax) {
  if (ray.r.degenerate) return 0u;
#if PT_ACCEL_SSE
  const triangle4_detail::Edges g = triangle4_detail::edges(tri, ray, tmax);
  return unsigned(_mm_movemask_ps(
             _mm_or_ps(_mm_andnot_ps(g.reject, _mm_cmpord_ps(g.det, g.det)), g.any_zero))) |
         unsigned(_mm_movemask_ps(_mm_cmpunord_ps(g.det, g.det)));
#else
  (void)tri, (void)tmax;
  return 0xFu;  // no SIMD: every lane goes to the exact test
#endif
}

/// Part 1's triangle test on four triangles at once, carried to the end in SIMD lanes where that
/// is bit for bit the scalar test, so a hit costs no second, scalar test.
struct Triangle4Hits {
  /// Lanes where intersect_sheared_triangle(ray, tmax, ...) hits, with exactly the t,
  /// barycentrics and t error bound below.
  unsigned hit = 0;
  /// Lanes only intersect_sheared_triangle can decide: an edge function of exactly 0 (it redoes
  /// those in double), a determinant that is not finite, a shear that is not (see ShearedRay4).
  unsigned retest = 0;
  alignas(16) float t[4], b0[4], b1[4], b2[4], t_error[4];
  /// The scaled distance and determinant, for still_hits().
  alignas(16) float t_scaled[4], det[4];

  /// Whether hit lane `lane` is still a hit of intersect_sheared_triangle with a nearer
  /// tmax (a traversal's cull shrinks as it finds hits): the test's two comparisons with tmax,
  /// the only ones that depend on it.
  bool still_hits(uint32_t lane, float tmax) const {
    const float d = det[lane], ts = t_scaled[lane];
    if (d > 0 ? ts >= tmax * d : ts <= tmax * d) return false;
    return t[lane] < tmax;
  }
};

/// Fills *out for the lanes in `lanes` (others may be reported too); the answer for any lane is
/// the one intersect_sheared_triangle(ray.r, tmax, corners of that lane) gives, or a retest.
inline void triangle4_intersect(const Triangle4& tri, const ShearedRay4& ray, float tmax,
                                unsigned lanes, Triangle4Hits* out) {
  out->hit = out->retest = 0;
  if (ray.r.degenerate) return;
#if PT_ACCEL_SSE
  using namespace triangle4_detail;
  const Edges g = edges(tri, ray, tmax);
  // The filter's candidates (see triangle4_candidates).
  const unsigned candidates =
      lanes & (unsigned(_mm_movemask_ps(_mm_or_ps(
                   _mm_andnot_ps(g.reject, _mm_cmpord_ps(g.det, g.det)), g.any_zero))) |
               unsigned(_mm_movemask_ps(_mm_cmpunord_ps(g.det, g.det))));
  if (candidates == 0) return;
  // With a finite determinant no edge function is infinite, so no sheared corner is either (an
  // infinite coordinate makes a product in two of them infinite or NaN): every max below is of
  // values that are not NaN, where _mm_max_ps is std::max.
  const __m128 finite = _mm_cmplt_ps(abs4(g.det), _mm_set1_ps(INFINITY));  // false for NaN
  const __m128 all = _mm_castsi128_ps(_mm_set1_epi32(-1));
  unsigned scalar = unsigned(_mm_movemask_ps(_mm_or_ps(g.any_zero, _mm_andnot_ps(finite, all))));
  if (!ray.finite_shear) scalar = 0xFu;
  out->retest = candidates & scalar;
  if ((candidates & ~scalar) == 0) return;

  const __m128 inv_det = _mm_div_ps(_mm_set1_ps(1.0f), g.det);
  const __m128 t = _mm_mul_ps(g.t_scaled, inv_det);
  const __m128 in_range =
      _mm_and_ps(_mm_cmpgt_ps(t, ray.tmin), _mm_cmplt_ps(t, _mm_set1_ps(tmax)));
  const __m128 max_z = max3(abs4(g.az), abs4(g.bz), abs4(g.cz));
  const __m128 max_x = max3(abs4(g.ax), abs4(g.bx), abs4(g.cx));
  const __m128 max_y = max3(abs4(g.ay), abs4(g.by), abs4(g.cy));
  const __m128 err_z = _mm_mul_ps(_mm_set1_ps(gamma(3)), max_z);
  const __m128 err_x = _mm_mul_ps(_mm_set1_ps(gamma(5)), _mm_add_ps(max_x, max_z));
  const __m128 err_y = _mm_mul_ps(_mm_set1_ps(gamma(5)), _mm_add_ps(max_y, max_z));
  const __m128 err_e = _mm_mul_ps(
      _mm_set1_ps(2.0f),
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(gamma(2)), max_x), max_y),
                            _mm_mul_ps(err_y, max_x)),
                 _mm_mul_ps(err_x, max_y)));
  const __m128 max_e = max3(abs4(g.e0), abs4(g.e1), abs4(g.e2));
  const __m128 err_t = _mm_mul_ps(
      _mm_mul_ps(_mm_set1_ps(3.0f),
                 _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(gamma(3)), max_e), max_z),
                                       _mm_mul_ps(err_e, max_z)),
                            _mm_mul_ps(err_z, max_e))),
      abs4(inv_det));
  // Rejected when t <= err_t, so a NaN bound rejects nothing.
  const __m128 accept = _mm_and_ps(in_range, _mm_cmpnle_ps(t, err_t));
  out->hit = candidates & ~scalar & unsigned(_mm_movemask_ps(accept));
  if (out->hit == 0) return;
  _mm_store_ps(out->t, t);
  _mm_store_ps(out->b0, _mm_mul_ps(g.e0, inv_det));
  _mm_store_ps(out->b1, _mm_mul_ps(g.e1, inv_det));
  _mm_store_ps(out->b2, _mm_mul_ps(g.e2, inv_det));
  _mm_store_ps(out->t_error, err_t);
  _mm_store_ps(out->t_scaled, g.t_scaled);
  _mm_store_ps(out->det, g.det);
#else
  (void)tri, (void)tmax;
  out->retest = lanes & 0xFu;  // no SIMD: every lane goes to the scalar test
#endif
}

}  // namespace pt
