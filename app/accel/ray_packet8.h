// Up to eight rays that leave one point (a shading point's shadow rays towards one light),
// prepared for box tests that answer each ray exactly as its own Box4Ray test does, and for a
// test of all of them at once that rules out the boxes no ray of the packet enters.
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#pragma once

#include <cmath>
#include <cstdint>

#include "app/accel/box4.h"
#include "app/fast/transpose8.h"
#include "framework/math/ray.h"

// The packet's lanes are gathered and compared with AVX2's integer lanes.
#if PT_ACCEL_AVX && defined(__AVX2__)
#define PT_ACCEL_PACKETS 1
#else
#define PT_ACCEL_PACKETS 0
#endif

namespace pt {

#if PT_ACCEL_PACKETS
/// Rays that leave one point, one a lane (a lane with no ray of the packet repeats the first's):
/// each ray's own origin, reciprocal direction and interval, as Box4Ray holds them, and for the
/// whole packet per axis the smallest and largest reciprocal, where they bound every ray's.
struct RayPacket8 {
  __m256 o[3], inv_d[3], tmin, tmax;
  float origin[3];
  /// Per axis: whether every ray's reciprocal is finite and of one sign, so the packet's plane
  /// distances are bounded by those of inv_lo and inv_hi (else that axis rules nothing out).
  bool bounded[3] = {};
  float inv_lo[3] = {}, inv_hi[3] = {};
  float tmin_lo = 0.0f, tmax_hi = 0.0f;
  /// Per axis, bit j set where lane j's reciprocal is negative (its sign bit, as Box4Ray takes
  /// a ray's octant).
  unsigned negative[3] = {};

  /// The octant lane j's box tests take the planes of.
  int octant(int j) const {
    return int(negative[0] >> j & 1u) | int(negative[1] >> j & 1u) << 1 |
           int(negative[2] >> j & 1u) << 2;
  }
  /// The rays of the packet: the first ray offered, if it is traceable (is_traceable), and each
  /// other traceable one that leaves its origin, to the bit.
  unsigned lanes = 0;
  /// The first ray offered, answered with the packet whether it is traceable or not.
  int first = 0;

  /// The packet of the first of rays[k], each bit k of `offered` (not zero), and those that can
  /// go with it.
  RayPacket8(const Ray* rays, unsigned offered) {
    first = __builtin_ctz(offered);
    static_assert(sizeof(Ray) == 8 * sizeof(float), "a ray is o, d, tmin, tmax side by side");
    // Each ray loaded whole (as it was stored, so the load is forwarded from the store), then
    // turned to one field a register.
    __m256 field[8];
    for (int j = 0; j < 8; ++j)
      field[j] = _mm256_loadu_ps(&(offered >> j & 1u ? rays[j] : rays[first]).o.x);
    transpose8(field);
    const __m256 inf = _mm256_set1_ps(INFINITY), sign = _mm256_set1_ps(-0.0f);
    const __m256 zero = _mm256_setzero_ps();
    auto bits = [](__m256 m) { return unsigned(_mm256_movemask_ps(m)); };
    auto finite = [&](__m256 v) { return bits(_mm256_cmp_ps(_mm256_andnot_ps(sign, v), inf, _CMP_LT_OQ)); };
    // is_traceable, lane by lane: a finite origin and direction, a direction not zero, no NaN
    // in the interval.
    unsigned traceable = bits(_mm256_cmp_ps(field[6], field[7], _CMP_ORD_Q));
    unsigned moving = 0;
    const Ray& head = rays[first];
    unsigned same = 0xFFu;
    for (int a = 0; a < 3; ++a) {
      o[a] = field[a];
      traceable &= finite(field[a]) & finite(field[3 + a]);
      moving |= bits(_mm256_cmp_ps(field[3 + a], zero, _CMP_NEQ_OQ));
      // Each lane's reciprocal, rounded as Box4Ray's division rounds it.
      inv_d[a] = _mm256_div_ps(_mm256_set1_ps(1.0f), field[3 + a]);
      negative[a] = bits(inv_d[a]);
      // The origin's bits, compared as integers: -0 is not 0 here.
      same &= bits(_mm256_castsi256_ps(_mm256_cmpeq_epi32(
          _mm256_castps_si256(o[a]), _mm256_castps_si256(_mm256_set1_ps(head.o[a])))));
    }
    traceable &= moving;
    tmin = field[6];
    tmax = field[7];
    lanes = offered & traceable & same & 0xFFu;
    if (lanes == 0) return;
    // Lanes outside the packet take the values of one inside, so the bounds are the packet's own.
    const int inside = __builtin_ctz(lanes);
    const __m256 keep = _mm256_castsi256_ps(_mm256_cmpgt_epi32(
        _mm256_and_si256(_mm256_set1_epi32(int(lanes)), _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128)),
        _mm256_setzero_si256()));
    auto packet_only = [&](__m256 v) {
      return _mm256_blendv_ps(_mm256_permutevar8x32_ps(v, _mm256_set1_epi32(inside)), v, keep);
    };
    for (int a = 0; a < 3; ++a) {
      origin[a] = head.o[a];
      const unsigned neg = negative[a] & lanes;
      bounded[a] = (finite(inv_d[a]) & lanes) == lanes && (neg == 0 || neg == lanes);
      inv_lo[a] = horizontal_min(packet_only(inv_d[a]));
      inv_hi[a] = horizontal_max(packet_only(inv_d[a]));
    }
    tmin_lo = horizontal_min(packet_only(tmin));
    tmax_hi = horizontal_max(packet_only(tmax));
  }

 private:
  static float horizontal_min(__m256 v) {
    __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_min_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_min_ss(m, _mm_shuffle_ps(m, m, 1)));
  }
  static float horizontal_max(__m256 v) {
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
  }
};

/// Which of the eight boxes of `boxes` some ray of the packet may enter: a superset of the boxes
/// its rays' own intersect_box8 tests enter. With one origin, a plane's distance (plane - o) is
/// the same for every ray, and rounding its product with a reciprocal is monotone in the
/// reciprocal, so on an axis where the reciprocals share a sign (and so the near and far planes)
/// the smallest and largest of them bound every ray's rounded distances; the maxima, minima and
/// scalings after it are monotone too. An axis without such bounds rules nothing out. One test
/// for the whole packet: a box it rules out costs no ray a test.
inline unsigned packet_may_enter8(const Box4 boxes[2], const RayPacket8& p) {
  __m256 tn = _mm256_set1_ps(-INFINITY), tf = _mm256_set1_ps(INFINITY);
  for (int a = 0; a < 3; ++a) {
    if (!p.bounded[a]) continue;
    const bool negative = std::signbit(p.inv_lo[a]);
    const __m256 o = _mm256_set1_ps(p.origin[a]);
    const __m256 lo = _mm256_set1_ps(p.inv_lo[a]), hi = _mm256_set1_ps(p.inv_hi[a]);
    const __m256 dn = _mm256_sub_ps(box_planes8(boxes, negative ? 3 + a : a), o);
    const __m256 df = _mm256_sub_ps(box_planes8(boxes, negative ? a : 3 + a), o);
    tn = _mm256_max_ps(_mm256_min_ps(_mm256_mul_ps(dn, lo), _mm256_mul_ps(dn, hi)), tn);
    tf = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(df, lo), _mm256_mul_ps(df, hi)), tf);
  }
  widen_slab_interval8(&tn, &tf);
  const __m256 t0 = _mm256_max_ps(tn, _mm256_set1_ps(p.tmin_lo));
  const __m256 t1 = _mm256_min_ps(tf, _mm256_set1_ps(p.tmax_hi));
  // Unordered counts as "may enter": a NaN bound culls nothing.
  return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_NGT_UQ)));
}

/// Which rays of the packet enter box `k` (slot k % 4 of boxes[k / 4]): bit j for lane j, each
/// lane the very operations of intersect_box8's test of that box for that ray (its planes
/// chosen by its own octant, its own tmin and tmax), so each bit is that test's answer.
inline unsigned rays_entering(const Box4 boxes[2], int k, const RayPacket8& p) {
  const Box4& box = boxes[k / 4];
  const int slot = k % 4;
  __m256 tn = _mm256_set1_ps(-INFINITY), tf = _mm256_set1_ps(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const __m256 lower = _mm256_set1_ps(box.bounds[a][slot]);
    const __m256 upper = _mm256_set1_ps(box.bounds[3 + a][slot]);
    // A negative reciprocal (its sign bit, -0's included) meets the upper plane first.
    const __m256 near_plane = _mm256_blendv_ps(lower, upper, p.inv_d[a]);
    const __m256 far_plane = _mm256_blendv_ps(upper, lower, p.inv_d[a]);
    const __m256 n = _mm256_mul_ps(_mm256_sub_ps(near_plane, p.o[a]), p.inv_d[a]);
    const __m256 f = _mm256_mul_ps(_mm256_sub_ps(far_plane, p.o[a]), p.inv_d[a]);
    tn = _mm256_max_ps(n, tn);
    tf = _mm256_min_ps(f, tf);
  }
  widen_slab_interval8(&tn, &tf);
  const __m256 t0 = _mm256_max_ps(tn, p.tmin);
  const __m256 t1 = _mm256_min_ps(tf, p.tmax);
  return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OS)));
}

/// Which of the eight boxes of `boxes` ray `j` of the packet enters: bit k for box k, each the
/// answer of intersect_box8's test of that ray (its lanes hold the ray's values, from the
/// packet's lane j, and the very operations).
inline unsigned ray_enters8(const Box4 boxes[2], int j, const RayPacket8& p) {
  const __m256i lane = _mm256_set1_epi32(j);
  const BoxPlanes& planes = kBoxPlanes[p.octant(j)];
  __m256 tn = _mm256_set1_ps(-INFINITY), tf = _mm256_set1_ps(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const __m256 o = _mm256_permutevar8x32_ps(p.o[a], lane);
    const __m256 inv = _mm256_permutevar8x32_ps(p.inv_d[a], lane);
    const __m256 n = _mm256_mul_ps(_mm256_sub_ps(box_planes8(boxes, planes.near_plane[a]), o), inv);
    const __m256 f = _mm256_mul_ps(_mm256_sub_ps(box_planes8(boxes, planes.far_plane[a]), o), inv);
    tn = _mm256_max_ps(n, tn);
    tf = _mm256_min_ps(f, tf);
  }
  widen_slab_interval8(&tn, &tf);
  const __m256 t0 = _mm256_max_ps(tn, _mm256_permutevar8x32_ps(p.tmin, lane));
  const __m256 t1 = _mm256_min_ps(tf, _mm256_permutevar8x32_ps(p.tmax, lane));
  return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OS)));
}
#endif

}  // namespace pt
