// Four triangles against one ray at once (SSE where the target has it), or eight (AVX): the
// sheared triangle test in SIMD lanes with the very same float operations, so most triangles of a
// leaf cost a fraction of a test and a hit comes with Part 1's t and barycentrics; only a lane
// with an edge function of exactly 0 (or a non-finite value) is handed back to the scalar test.
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

#if PT_SSE2
/// A sheared ray's per-ray values in every lane of a four-lane register.
struct ShearedLanes4 {
  __m128 o[3], sx, sy, sz, tmin;
};
#endif
#if PT_ACCEL_AVX
/// The same in every lane of an eight-lane register.
struct ShearedLanes8 {
  __m256 o[3], sx, sy, sz, tmin;
};
#endif

/// A sheared ray with its per-ray values in every lane.
struct ShearedRay4 {
#if PT_ACCEL_AVX
  ShearedLanes8 v8;  ///< the four-lane tests read its lower halves (lanes_of): no second copy
#elif PT_SSE2
  ShearedLanes4 v4;
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
#if PT_ACCEL_AVX
    for (int a = 0; a < 3; ++a) v8.o[a] = _mm256_set1_ps(r.o[a]);
    v8.sx = _mm256_set1_ps(r.sx), v8.sy = _mm256_set1_ps(r.sy), v8.sz = _mm256_set1_ps(r.sz);
    v8.tmin = _mm256_set1_ps(r.tmin);
#elif PT_SSE2
    for (int a = 0; a < 3; ++a) v4.o[a] = _mm_set1_ps(r.o[a]);
    v4.sx = _mm_set1_ps(r.sx), v4.sy = _mm_set1_ps(r.sy), v4.sz = _mm_set1_ps(r.sz);
    v4.tmin = _mm_set1_ps(r.tmin);
#endif
  }
};

#if PT_SSE2
namespace triangle4_detail {

// The operations the test needs, for four lanes (__m128) and eight (__m256) alike, so that one
// template below is the test for both: the same operations in the same order, lane by lane.
inline __m128 add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
inline __m128 sub(__m128 a, __m128 b) { return _mm_sub_ps(a, b); }
inline __m128 mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
inline __m128 div(__m128 a, __m128 b) { return _mm_div_ps(a, b); }
inline __m128 max(__m128 a, __m128 b) { return _mm_max_ps(a, b); }
inline __m128 bit_or(__m128 a, __m128 b) { return _mm_or_ps(a, b); }
inline __m128 bit_and(__m128 a, __m128 b) { return _mm_and_ps(a, b); }
inline __m128 and_not(__m128 a, __m128 b) { return _mm_andnot_ps(a, b); }  ///< ~a & b
inline __m128 eq(__m128 a, __m128 b) { return _mm_cmpeq_ps(a, b); }
inline __m128 lt(__m128 a, __m128 b) { return _mm_cmplt_ps(a, b); }
inline __m128 le(__m128 a, __m128 b) { return _mm_cmple_ps(a, b); }
inline __m128 gt(__m128 a, __m128 b) { return _mm_cmpgt_ps(a, b); }
inline __m128 ge(__m128 a, __m128 b) { return _mm_cmpge_ps(a, b); }
inline __m128 not_le(__m128 a, __m128 b) { return _mm_cmpnle_ps(a, b); }
inline __m128 ordered(__m128 a, __m128 b) { return _mm_cmpord_ps(a, b); }
inline __m128 unordered(__m128 a, __m128 b) { return _mm_cmpunord_ps(a, b); }
inline unsigned mask_of(__m128 a) { return unsigned(_mm_movemask_ps(a)); }
inline void store(float* p, __m128 a) { _mm_store_ps(p, a); }
template <class V> V splat(float x);
template <> inline __m128 splat<__m128>(float x) { return _mm_set1_ps(x); }
inline __m128 all_ones(__m128) { return _mm_castsi128_ps(_mm_set1_epi32(-1)); }
#if PT_ACCEL_AVX
inline ShearedLanes4 lanes_of(const ShearedRay4& r, __m128) {
  const ShearedLanes8& v = r.v8;
  return {{_mm256_castps256_ps128(v.o[0]), _mm256_castps256_ps128(v.o[1]),
           _mm256_castps256_ps128(v.o[2])},
          _mm256_castps256_ps128(v.sx), _mm256_castps256_ps128(v.sy),
          _mm256_castps256_ps128(v.sz), _mm256_castps256_ps128(v.tmin)};
}
#else
inline const ShearedLanes4& lanes_of(const ShearedRay4& r, __m128) { return r.v4; }
#endif
#if PT_ACCEL_AVX
inline __m256 add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
inline __m256 sub(__m256 a, __m256 b) { return _mm256_sub_ps(a, b); }
inline __m256 mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
inline __m256 div(__m256 a, __m256 b) { return _mm256_div_ps(a, b); }
inline __m256 max(__m256 a, __m256 b) { return _mm256_max_ps(a, b); }
inline __m256 bit_or(__m256 a, __m256 b) { return _mm256_or_ps(a, b); }
inline __m256 bit_and(__m256 a, __m256 b) { return _mm256_and_ps(a, b); }
inline __m256 and_not(__m256 a, __m256 b) { return _mm256_andnot_ps(a, b); }
// The predicates SSE's comparisons compute (cmple is "less or equal, ordered", and so on).
inline __m256 eq(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
inline __m256 lt(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_LT_OS); }
inline __m256 le(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_LE_OS); }
inline __m256 gt(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
inline __m256 ge(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_GE_OS); }
inline __m256 not_le(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_NLE_US); }
inline __m256 ordered(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_ORD_Q); }
inline __m256 unordered(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_UNORD_Q); }
inline unsigned mask_of(__m256 a) { return unsigned(_mm256_movemask_ps(a)); }
inline void store(float* p, __m256 a) { _mm256_store_ps(p, a); }
template <> inline __m256 splat<__m256>(float x) { return _mm256_set1_ps(x); }
inline __m256 all_ones(__m256) { return _mm256_castsi256_ps(_mm256_set1_epi32(-1)); }
inline const ShearedLanes8& lanes_of(const ShearedRay4& r, __m256) { return r.v8; }
#endif

/// A corner coordinate of every lane: one packet's (four lanes) or two packets' side by side
/// (eight lanes, the first packet low).
inline __m128 load_corner(const Triangle4* const tri[1], int c, int axis, __m128) {
  return _mm_load_ps(tri[0]->corner[c][axis]);
}
#if PT_ACCEL_AVX
inline __m256 load_corner(const Triangle4* const tri[2], int c, int axis, __m256) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(tri[0]->corner[c][axis])),
                              _mm_load_ps(tri[1]->corner[c][axis]), 1);
}
#endif

/// The first steps of intersect_sheared_triangle in SIMD lanes, with its very operations: the
/// corners relative to the origin and sheared, the edge functions, their sum and the scaled t.
template <class V>
struct Edges {
  V ax, ay, az, bx, by, bz, cx, cy, cz;  ///< sheared corners, z scaled by sz
  V e0, e1, e2, det, t_scaled;
  V any_zero;  ///< an edge function of exactly 0, which the scalar test redoes in double
  V reject;    ///< what the scalar test rejects, by the same comparisons (valid where no zero)
};

template <class V>
__attribute__((always_inline)) inline Edges<V> edges(const Triangle4* const tri[], const ShearedRay4& ray, float tmax) {
  const V tag{};
  const auto& r = lanes_of(ray, tag);
  Edges<V> g;
  const int kx = ray.r.kx, ky = ray.r.ky, kz = ray.r.kz;
  g.ax = sub(load_corner(tri, 0, kx, tag), r.o[kx]);
  g.ay = sub(load_corner(tri, 0, ky, tag), r.o[ky]);
  g.az = sub(load_corner(tri, 0, kz, tag), r.o[kz]);
  g.bx = sub(load_corner(tri, 1, kx, tag), r.o[kx]);
  g.by = sub(load_corner(tri, 1, ky, tag), r.o[ky]);
  g.bz = sub(load_corner(tri, 1, kz, tag), r.o[kz]);
  g.cx = sub(load_corner(tri, 2, kx, tag), r.o[kx]);
  g.cy = sub(load_corner(tri, 2, ky, tag), r.o[ky]);
  g.cz = sub(load_corner(tri, 2, kz, tag), r.o[kz]);
  g.ax = add(g.ax, mul(r.sx, g.az)), g.ay = add(g.ay, mul(r.sy, g.az));
  g.bx = add(g.bx, mul(r.sx, g.bz)), g.by = add(g.by, mul(r.sy, g.bz));
  g.cx = add(g.cx, mul(r.sx, g.cz)), g.cy = add(g.cy, mul(r.sy, g.cz));
  g.e0 = sub(mul(g.bx, g.cy), mul(g.by, g.cx));
  g.e1 = sub(mul(g.cx, g.ay), mul(g.cy, g.ax));
  g.e2 = sub(mul(g.ax, g.by), mul(g.ay, g.bx));
  const V zero = splat<V>(0.0f);
  g.any_zero = bit_or(bit_or(eq(g.e0, zero), eq(g.e1, zero)), eq(g.e2, zero));
  const V any_neg = bit_or(bit_or(lt(g.e0, zero), lt(g.e1, zero)), lt(g.e2, zero));
  const V any_pos = bit_or(bit_or(gt(g.e0, zero), gt(g.e1, zero)), gt(g.e2, zero));
  g.det = add(add(g.e0, g.e1), g.e2);
  g.az = mul(g.az, r.sz), g.bz = mul(g.bz, r.sz), g.cz = mul(g.cz, r.sz);
  g.t_scaled = add(add(mul(g.e0, g.az), mul(g.e1, g.bz)), mul(g.e2, g.cz));
  const V lo = mul(r.tmin, g.det), hi = mul(splat<V>(tmax), g.det);
  const V positive = gt(g.det, zero);
  // det > 0: out when t_scaled <= tmin·det or >= tmax·det; det < 0 (or NaN): the mirror image.
  const V out_pos = bit_or(le(g.t_scaled, lo), ge(g.t_scaled, hi));
  const V out_neg = bit_or(ge(g.t_scaled, lo), le(g.t_scaled, hi));
  const V out_t = bit_or(bit_and(positive, out_pos), and_not(positive, out_neg));
  g.reject = bit_or(bit_and(any_neg, any_pos), bit_or(eq(g.det, zero), out_t));
  return g;
}

template <class V>
inline V abs_lanes(V v) { return and_not(splat<V>(-0.0f), v); }
/// std::max({a, b, c}) for values that are not NaN.
template <class V>
inline V max3(V a, V b, V c) { return max(max(a, b), c); }

/// The filter's candidates (see triangle4_candidates) among the lanes of `g`.
template <class V>
inline unsigned candidates_of(const Edges<V>& g) {
  return mask_of(bit_or(and_not(g.reject, ordered(g.det, g.det)), g.any_zero)) |
         mask_of(unordered(g.det, g.det));
}

}  // namespace triangle4_detail
#endif

/// The lanes (bit k for lane k) that intersect_sheared_triangle(ray, tmax, ...) may accept: every
/// other lane it would reject, by the same comparisons of bit-identical values (edge functions of
/// mixed signs, a zero determinant, t outside the interval). A lane with an edge function of
/// exactly 0 (which the exact test recomputes in double) or a NaN is always a candidate.
inline unsigned triangle4_candidates(const Triangle4& tri, const ShearedRay4& ray, float tmax) {
  if (ray.r.degenerate) return 0u;
#if PT_SSE2
  const Triangle4* const packets[1] = {&tri};
  return triangle4_detail::candidates_of(triangle4_detail::edges<__m128>(packets, ray, tmax));
#else
  (void)tri, (void)tmax;
  return 0xFu;  // no SIMD: every lane goes to the exact test
#endif
}

/// Part 1's triangle test on N triangles at once (four, or eight where the build has AVX),
/// carried to the end in SIMD lanes where that is bit for bit the scalar test, so a hit costs no
/// second, scalar test.
template <int N>
struct TriangleLaneHits {
  /// Lanes where intersect_sheared_triangle(ray, tmax, ...) hits, with exactly the t,
  /// barycentrics and t error bound below.
  unsigned hit = 0;
  /// Lanes only intersect_sheared_triangle can decide: an edge function of exactly 0 (it redoes
  /// those in double), a determinant that is not finite, a shear that is not (see ShearedRay4).
  unsigned retest = 0;
  alignas(32) float t[N], b0[N], b1[N], b2[N], t_error[N];
  /// The scaled distance and determinant, for still_hits().
  alignas(32) float t_scaled[N], det[N];

  /// Whether hit lane `lane` is still a hit of intersect_sheared_triangle with a nearer
  /// tmax (a traversal's cull shrinks as it finds hits): the test's two comparisons with tmax,
  /// the only ones that depend on it.
  bool still_hits(uint32_t lane, float tmax) const {
    const float d = det[lane], ts = t_scaled[lane];
    if (d > 0 ? ts >= tmax * d : ts <= tmax * d) return false;
    return t[lane] < tmax;
  }
};
using Triangle4Hits = TriangleLaneHits<4>;
using Triangle8Hits = TriangleLaneHits<8>;

#if PT_SSE2
namespace triangle4_detail {

/// The whole test in the lanes of V over the packets `tri` (one for __m128, two for __m256).
// Always inlined: called from every leaf visit, an out-of-line call spilled the ray's lanes and
// the cull around each test.
template <class V, int N>
__attribute__((always_inline)) inline void intersect_lanes(const Triangle4* const tri[], const ShearedRay4& ray, float tmax,
                            unsigned lanes, TriangleLaneHits<N>* out) {
  out->hit = out->retest = 0;
  if (ray.r.degenerate) return;
  const Edges<V> g = edges<V>(tri, ray, tmax);
  const unsigned candidates = lanes & candidates_of(g);
  if (candidates == 0) return;
  // With a finite determinant no edge function is infinite, so no sheared corner is either (an
  // infinite coordinate makes a product in two of them infinite or NaN): every max below is of
  // values that are not NaN, where _mm_max_ps is std::max.
  const V finite = lt(abs_lanes(g.det), splat<V>(INFINITY));  // false for NaN
  unsigned scalar = mask_of(bit_or(g.any_zero, and_not(finite, all_ones(finite))));
  if (!ray.finite_shear) scalar = (1u << N) - 1u;
  out->retest = candidates & scalar;
  if ((candidates & ~scalar) == 0) return;

  const auto& r = lanes_of(ray, V{});
  const V inv_det = div(splat<V>(1.0f), g.det);
  const V t = mul(g.t_scaled, inv_det);
  const V in_range = bit_and(gt(t, r.tmin), lt(t, splat<V>(tmax)));
  const V max_z = max3(abs_lanes(g.az), abs_lanes(g.bz), abs_lanes(g.cz));
  const V max_x = max3(abs_lanes(g.ax), abs_lanes(g.bx), abs_lanes(g.cx));
  const V max_y = max3(abs_lanes(g.ay), abs_lanes(g.by), abs_lanes(g.cy));
  const V err_z = mul(splat<V>(gamma(3)), max_z);
  const V err_x = mul(splat<V>(gamma(5)), add(max_x, max_z));
  const V err_y = mul(splat<V>(gamma(5)), add(max_y, max_z));
  const V err_e = mul(splat<V>(2.0f), add(add(mul(mul(splat<V>(gamma(2)), max_x), max_y),
                                              mul(err_y, max_x)),
                                          mul(err_x, max_y)));
  const V max_e = max3(abs_lanes(g.e0), abs_lanes(g.e1), abs_lanes(g.e2));
  const V err_t = mul(mul(splat<V>(3.0f), add(add(mul(mul(splat<V>(gamma(3)), max_e), max_z),
                                                  mul(err_e, max_z)),
                                              mul(err_z, max_e))),
                      abs_lanes(inv_det));
  // Rejected when t <= err_t, so a NaN bound rejects nothing.
  const V accept = bit_and(in_range, not_le(t, err_t));
  out->hit = candidates & ~scalar & mask_of(accept);
  if (out->hit == 0) return;
  store(out->t, t);
  store(out->b0, mul(g.e0, inv_det));
  store(out->b1, mul(g.e1, inv_det));
  store(out->b2, mul(g.e2, inv_det));
  store(out->t_error, err_t);
  store(out->t_scaled, g.t_scaled);
  store(out->det, g.det);
}

}  // namespace triangle4_detail
#endif

/// Fills *out for the lanes in `lanes` (others may be reported too); the answer for any lane is
/// the one intersect_sheared_triangle(ray.r, tmax, corners of that lane) gives, or a retest.
/// Always inlined (as is the eight-lane form below): it runs at every leaf a ray enters.
__attribute__((always_inline)) inline void triangle4_intersect(const Triangle4& tri,
                                                               const ShearedRay4& ray, float tmax,
                                                               unsigned lanes, Triangle4Hits* out) {
#if PT_SSE2
  const Triangle4* const packets[1] = {&tri};
  triangle4_detail::intersect_lanes<__m128>(packets, ray, tmax, lanes, out);
#else
  (void)tri, (void)tmax, (void)ray;
  out->hit = 0;
  out->retest = lanes & 0xFu;  // no SIMD: every lane goes to the scalar test
#endif
}

/// triangle4_intersect on two packets at once: lane k of the result is lane k % 4 of packet
/// k / 4 (`lanes` likewise). One eight-lane test where the build has AVX, else two four-lane ones;
/// the same answers either way.
__attribute__((always_inline)) inline void triangle8_intersect(const Triangle4& first,
                                                               const Triangle4& second,
                                                               const ShearedRay4& ray, float tmax,
                                                               unsigned lanes, Triangle8Hits* out) {
#if PT_ACCEL_AVX
  const Triangle4* const packets[2] = {&first, &second};
  triangle4_detail::intersect_lanes<__m256>(packets, ray, tmax, lanes, out);
#else
  Triangle4Hits h[2];
  triangle4_intersect(first, ray, tmax, lanes & 0xFu, &h[0]);
  triangle4_intersect(second, ray, tmax, lanes >> 4 & 0xFu, &h[1]);
  out->hit = h[0].hit | h[1].hit << 4;
  out->retest = h[0].retest | h[1].retest << 4;
  for (unsigned bits = out->hit; bits; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    const Triangle4Hits& s = h[k / 4];
    out->t[k] = s.t[k % 4], out->b0[k] = s.b0[k % 4], out->b1[k] = s.b1[k % 4];
    out->b2[k] = s.b2[k % 4], out->t_error[k] = s.t_error[k % 4];
    out->t_scaled[k] = s.t_scaled[k % 4], out->det[k] = s.det[k % 4];
  }
#endif
}

}  // namespace pt
