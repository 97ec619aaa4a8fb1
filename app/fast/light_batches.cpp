// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#include "app/fast/light_batches.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "app/fast/lane_rays.h"
#include "app/fast/transpose8.h"
#include "app/fast/vec3_lanes.h"
#include "framework/math/float_error.h"
#if PT_SSE2 && defined(__AVX__)
#include <immintrin.h>
#endif

namespace pt {
namespace {

#if PT_SSE2 && defined(__AVX__)
// A quad panel's samples for eight numbers u[0..8) at once, one a lane: every operation of the
// framework's sample of a quad (light_set.cpp's finish_surface_sample, for corner + u.x·edge_u +
// u.y·edge_v), in its order, on eight lanes, so each lane's bits are the ones make_sample makes
// (light_batches_test checks it). A lane with no sample (p on the light, the back of the panel)
// gets LightSample{}. Each sample is written as two 32-byte stores and one of 8 (floats 0-7,
// 8-15, then n.z with delta false), after transposing the fields to samples: a caller's loads
// (glm's, the estimate's, merged by the compiler as it likes) are forwarded from a store only
// when one store holds all their bytes. Where the build has AVX2 and `from` is the point asking,
// each found sample's shadow ray is made too, into rays[j], and the bits of the found lanes are
// returned; 0 otherwise.
int sample_quad8(const SampledLight& l, const glm::vec3& p, const glm::vec2 u[8], LightSample out[8],
                 const SurfaceHit* from_point, Ray rays[8]) {
  static_assert(offsetof(LightSample, wi) == 0 && offsetof(LightSample, L) == 12 &&
                    offsetof(LightSample, pdf) == 24 &&
                    offsetof(LightSample, target.distance) == 28 &&
                    offsetof(LightSample, target.p) == 32 &&
                    offsetof(LightSample, target.p_error) == 44 &&
                    offsetof(LightSample, target.n) == 56 &&
                    offsetof(LightSample, target.delta) == 68 &&
                    sizeof(LightSample) == 72,
                "the rows below are LightSample's fields in order");
  static_assert(sizeof(Ray) == 8 * sizeof(float), "a ray is o, d, tmin, tmax side by side");
  auto splat = [](float x) { return _mm256_set1_ps(x); };
  const __m256 ux = _mm256_setr_ps(u[0].x, u[1].x, u[2].x, u[3].x, u[4].x, u[5].x, u[6].x, u[7].x);
  const __m256 uy = _mm256_setr_ps(u[0].y, u[1].y, u[2].y, u[3].y, u[4].y, u[5].y, u[6].y, u[7].y);
  const __m256 sign = splat(-0.0f);
  const glm::vec3& n = l.normal;
  __m256 q[3], d[3], wa_abs[3];
  for (int k = 0; k < 3; ++k) {
    const __m256 wa = splat(l.corner[k]);
    const __m256 wb = _mm256_mul_ps(ux, splat(l.edge_u[k]));
    const __m256 wc = _mm256_mul_ps(uy, splat(l.edge_v[k]));
    q[k] = _mm256_add_ps(_mm256_add_ps(wa, wb), wc);
    d[k] = _mm256_sub_ps(q[k], splat(p[k]));
    wa_abs[k] = _mm256_add_ps(_mm256_add_ps(_mm256_andnot_ps(sign, wa), _mm256_andnot_ps(sign, wb)),
                              _mm256_andnot_ps(sign, wc));
  }
  const __m256 dd = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(d[0], d[0]), _mm256_mul_ps(d[1], d[1])),
                                  _mm256_mul_ps(d[2], d[2]));
  const __m256 dist = _mm256_sqrt_ps(dd);
  __m256 found = _mm256_and_ps(_mm256_cmp_ps(dist, _mm256_setzero_ps(), _CMP_GT_OQ),
                               _mm256_cmp_ps(dist, splat(std::numeric_limits<float>::infinity()),
                                             _CMP_NEQ_UQ));
  __m256 wi[3], cos_l = _mm256_setzero_ps();
  for (int k = 0; k < 3; ++k) {
    wi[k] = _mm256_div_ps(d[k], dist);
    const __m256 term = _mm256_mul_ps(_mm256_xor_ps(wi[k], sign), splat(n[k]));
    cos_l = k == 0 ? term : _mm256_add_ps(cos_l, term);
  }
  found = _mm256_and_ps(found, _mm256_cmp_ps(cos_l, _mm256_setzero_ps(), _CMP_GT_OQ));
  // area_to_solid_angle_pdf: 1/area · dist · dist / |cos|, zero where |cos| is not positive.
  const __m256 c = _mm256_andnot_ps(sign, cos_l);
  const __m256 pdf = _mm256_and_ps(
      _mm256_cmp_ps(c, _mm256_setzero_ps(), _CMP_GT_OQ),
      _mm256_div_ps(_mm256_mul_ps(_mm256_mul_ps(splat(l.inv_area), dist), dist), c));
  const __m256 lit = _mm256_and_ps(found, _mm256_cmp_ps(pdf, _mm256_setzero_ps(), _CMP_GT_OQ));
  // The rows: LightSample's 18 floats (the last, delta and padding, zero), each masked to its
  // lane's `found` (LightSample{} elsewhere: zeros, and an infinite distance).
  __m256 first[8] = {wi[0], wi[1], wi[2],
                     _mm256_and_ps(lit, splat(l.radiance.x)), _mm256_and_ps(lit, splat(l.radiance.y)),
                     _mm256_and_ps(lit, splat(l.radiance.z)), pdf, dist};
  for (int k = 0; k < 7; ++k) first[k] = _mm256_and_ps(found, first[k]);
  first[7] = _mm256_blendv_ps(splat(std::numeric_limits<float>::infinity()), dist, found);
  __m256 second[8];
  for (int k = 0; k < 3; ++k) {
    second[k] = _mm256_and_ps(found, q[k]);
    second[3 + k] = _mm256_and_ps(
        found, _mm256_add_ps(_mm256_mul_ps(splat(gamma(6)), wa_abs[k]), splat(l.panel_slack[k])));
  }
  second[6] = _mm256_and_ps(found, splat(n.x));
  second[7] = _mm256_and_ps(found, splat(n.y));
  const __m256 nz = _mm256_and_ps(found, splat(n.z));
  int made = 0;
#ifdef __AVX2__
  if (from_point) {
    const SurfaceHit& from = *from_point;
    // Each found sample's shadow ray, as make_shadow_ray makes it (framework's spawn_ray_to):
    // its operations in their order, so each lane's bits are the ray's. The origin is the
    // point's own offset, turned to the side each direction leaves by: one point a side.
    using namespace lanes;
    const V3 hng = load(from.ng), hp = load(from.p);
    const V3 offset = mul(_mm_set1_ps(lanes::dot(glm_abs(hng), load(from.p_error))), hng);
    alignas(16) float up[4], down[4];
    _mm_store_ps(up, round_away(add(hp, offset), offset));
    _mm_store_ps(down, round_away(add(hp, neg(offset)), neg(offset)));
    auto dot8 = [](const __m256* a, const __m256* b) {
      return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], b[0]), _mm256_mul_ps(a[1], b[1])),
                           _mm256_mul_ps(a[2], b[2]));
    };
    const __m256 zero = _mm256_setzero_ps();
    const __m256 w[3] = {first[0], first[1], first[2]};
    const __m256 ng8[3] = {splat(from.ng.x), splat(from.ng.y), splat(from.ng.z)};
    const __m256 below = _mm256_cmp_ps(dot8(w, ng8), zero, _CMP_LT_OQ);
    // The target: the light's point offset off it towards the shading point (-wi), or the point
    // itself where the light has no normal.
    const __m256 ln[3] = {second[6], second[7], nz};
    const __m256 abs_ln[3] = {glm_abs(ln[0]), glm_abs(ln[1]), glm_abs(ln[2])};
    const __m256 spread = dot8(abs_ln, second + 3);
    const __m256 minus_w[3] = {_mm256_xor_ps(w[0], sign), _mm256_xor_ps(w[1], sign),
                               _mm256_xor_ps(w[2], sign)};
    const __m256 flip = _mm256_and_ps(_mm256_cmp_ps(dot8(minus_w, ln), zero, _CMP_LT_OQ), sign);
    const __m256 no_normal = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(ln[0], zero, _CMP_EQ_OQ), _mm256_cmp_ps(ln[1], zero, _CMP_EQ_OQ)),
        _mm256_cmp_ps(ln[2], zero, _CMP_EQ_OQ));
    __m256 o[3], d[3];
    for (int k = 0; k < 3; ++k) {
      o[k] = _mm256_blendv_ps(splat(up[k]), splat(down[k]), below);
      const __m256 off = _mm256_xor_ps(_mm256_mul_ps(spread, ln[k]), flip);
      const __m256 target = _mm256_blendv_ps(round_away(_mm256_add_ps(second[k], off), off), second[k],
                                             no_normal);
      d[k] = _mm256_sub_ps(target, o[k]);
    }
    const __m256 len = _mm256_sqrt_ps(dot8(d, d));
    const __m256 aimed = _mm256_cmp_ps(len, zero, _CMP_GT_OQ);  // else an empty ray along wi
    __m256 ray[8];
    for (int k = 0; k < 3; ++k) {
      ray[k] = o[k];
      ray[3 + k] = _mm256_blendv_ps(w[k], _mm256_div_ps(d[k], len), aimed);
    }
    ray[6] = zero;
    ray[7] = _mm256_and_ps(aimed, _mm256_mul_ps(len, splat(1.0f - gamma(4))));
    made = _mm256_movemask_ps(found);
    transpose8(ray);
    for (int j = 0; j < 8; ++j) _mm256_storeu_ps(reinterpret_cast<float*>(&rays[j]), ray[j]);
  }
#else
  (void)from_point;
#endif
  transpose8(first);
  transpose8(second);
  alignas(32) float last[8];
  _mm256_store_ps(last, nz);
  for (int j = 0; j < 8; ++j) {
    float* to = reinterpret_cast<float*>(&out[j]);
    _mm256_storeu_ps(to, first[j]);
    _mm256_storeu_ps(to + 8, second[j]);
    _mm_storel_pi(reinterpret_cast<__m64*>(to + 16), _mm_set_ss(last[j]));  // n.z; delta false
  }
  return made;
}
#endif

}  // namespace

// In three 32-byte comparisons and two of 4 bytes where the build has AVX2.
bool LightBatches::same_as_made(const SurfaceHit& hit, const LightSample& ls,
                                const LightSample& made, const float from[9]) {
  static_assert(offsetof(LightSample, target.n) + 3 * sizeof(float) ==
                        offsetof(LightSample, target.delta) &&
                    offsetof(SurfaceHit, ng) + 3 * sizeof(float) - offsetof(SurfaceHit, p) ==
                        9 * sizeof(float),
                "the sample's floats 0-16 and the point's p, p_error, ng side by side");
  const char* s = reinterpret_cast<const char*>(&ls);
  const char* m = reinterpret_cast<const char*>(&made);
  const char* h = reinterpret_cast<const char*>(&hit) + offsetof(SurfaceHit, p);
  const char* f = reinterpret_cast<const char*>(from);
#if defined(__AVX2__)
  auto at = [](const char* b) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b)); };
  const __m256i differ = _mm256_or_si256(
      _mm256_or_si256(_mm256_xor_si256(at(s), at(m)), _mm256_xor_si256(at(s + 32), at(m + 32))),
      _mm256_xor_si256(at(h), at(f)));
  if (!_mm256_testz_si256(differ, differ)) return false;
#else
  if (std::memcmp(s, m, 64) != 0 || std::memcmp(h, f, 32) != 0) return false;
#endif
  return std::memcmp(s + 64, m + 64, 4) == 0 && ls.target.delta == made.target.delta &&
         std::memcmp(h + 32, f + 32, 4) == 0;
}

LightSample LightBatches::copy_of(const LightSample& ls) {
  LightSample out;
#if PT_SSE2 && defined(__AVX__)
  // As sample_quad8 writes it, so the caller's loads of the copy are forwarded as above.
  const float* from = reinterpret_cast<const float*>(&ls);
  float* to = reinterpret_cast<float*>(&out);
  _mm256_storeu_ps(to, _mm256_loadu_ps(from));
  _mm256_storeu_ps(to + 8, _mm256_loadu_ps(from + 8));
  _mm_storel_pi(reinterpret_cast<__m64*>(to + 16), _mm_castsi128_ps(_mm_loadl_epi64(
                                                        reinterpret_cast<const __m128i*>(from + 16))));
#else
  out = ls;
#endif
  return out;
}

LightSample LightBatches::sample_anew(const SampledLights& set, int index,
                                      const SurfaceHit& hit, glm::vec2 u) {
  // The batch before is done: its counts are settled here, off the path of the calls it answered.
  const int answered = before_ + next_;
  answered_ahead_ += std::max(0, next_ - 1);
  if (next_ < count_) {
    // Foreseen samples the estimate did not ask for: it draws its numbers some other way, and
    // making more would only cost time. The rest of this camera sample is sampled call by call.
    made_in_vain_ += count_ - next_;
    foresee_ = false;
  }
  before_ = &set == set_ && index == light_ && same_bits(hit.p, p_) ? answered : 0;
  set_ = &set;
  light_ = index;
  p_ = hit.p;
  rays_made_ = 0;
  traced_ = occluded_ = 0;
  const int want = std::min(kBatch, light_samples_ - before_);
  const SampledLight& l = set.lights()[index];
  const bool batches = l.kind == SampledLightKind::panel || l.kind == SampledLightKind::mesh;
  if (!foresee_ || want < 2 || !batches) {
    count_ = next_ = 0;
    ++before_;
    return set.make_sample(index, hit, u);
  }
  u_[0] = u;
  Rng ahead = *rng_;
  for (int j = 1; j < want; ++j) u_[j] = ahead.next_2d();
#if PT_SSE2 && defined(__AVX__)
  if (l.quad) {
    // Eight lanes whatever `want` is: the spare ones repeat u[0].
    for (int j = want; j < kBatch; ++j) u_[j] = u_[0];
    static_assert(offsetof(SurfaceHit, ng) - offsetof(SurfaceHit, p) == 6 * sizeof(float),
                  "p, p_error and ng side by side");
    std::memcpy(from_, reinterpret_cast<const char*>(&hit) + offsetof(SurfaceHit, p), sizeof from_);
    rays_made_ = sample_quad8(l, hit.p, u_, batch_.at, &hit, rays_.at);
  } else
#endif
  {
    for (int j = 0; j < want; ++j) batch_.at[j] = set.make_sample(index, hit, u_[j]);
  }
  count_ = want;
  next_ = 1;
  last_ = 0;
  return copy_of(batch_.at[0]);
}

void LightBatches::trace_packet() {
  // The rays from last_ on not yet traced: the tracer takes ray last_ and those that leave its
  // point (the samples on the surface's side the estimate is tracing; a sample below the surface
  // is never traced, and leaves the other point).
  const unsigned offered = unsigned(rays_made_) & ~traced_ & (0xFFu << last_) & ((1u << count_) - 1u);
  unsigned answered = 0;
  occluded_ |= tracer_.occluded(tracer_.query, rays_.at, offered, &answered) & answered;
  traced_ |= answered;
  ++packets_;
  packet_rays_ += __builtin_popcount(answered);
}

Ray LightBatches::shadow_ray_anew(const SurfaceHit& hit, const LightSample& ls) {
  const ShadowTarget& to = ls.target;
  return std::isfinite(to.distance) ? spawn_ray_to_in_lanes(hit, ls.wi, to.p, to.p_error, to.n)
                                    : spawn_ray_in_lanes(hit, ls.wi);
}

}  // namespace pt
