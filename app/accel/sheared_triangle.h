// Part 1's watertight ray-triangle test split in two: what depends on the ray alone, computed once
// per ray, and what each triangle costs, with the very same float operations (bit-identical t and
// barycentrics), so a traversal can test thousands of triangles without redoing the shear.
// SOLUTION-ONLY FILE: not in the student handout, since it holds complete Part 1 and Part 2 answers.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/surface_hit.h"
#include "framework/math/float_error.h"
#include "framework/math/ray.h"
#include "app/fast/sse.h"

namespace pt {

/// A ray prepared for many triangle tests: the axis permutation that makes the direction's largest
/// component z and the shear that turns the direction into +z (Woop, Benthin and Wald 2013).
/// Computed exactly as Part 1's intersect_triangle computes them, so the per-triangle part below
/// rounds the same way.
struct ShearedRay {
  glm::vec3 o{0.0f};
  int kx = 0, ky = 1, kz = 2;
  float sx = 0.0f, sy = 0.0f, sz = 1.0f;
  float tmin = 0.0f;
  bool degenerate = true;  ///< a zero direction meets nothing

  ShearedRay() = default;
  // Always inlined: once per ray, and an out-of-line call cost more than its body.
  __attribute__((always_inline)) explicit ShearedRay(const Ray& ray) : o(ray.o), tmin(ray.tmin) {
    const glm::vec3 ad = glm::abs(ray.d);
    kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    degenerate = ray.d[kz] == 0.0f;
    kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    const glm::vec3 d(ray.d[kx], ray.d[ky], ray.d[kz]);
#if PT_SSE2
    // The three quotients in one division of four lanes: each lane is the correctly rounded
    // quotient, as the scalar division's, and a shadow ray waited on three divisions in a row.
    alignas(16) float q[4];
    _mm_store_ps(q, _mm_div_ps(_mm_setr_ps(-d.x, -d.y, 1.0f, 1.0f), _mm_set1_ps(d.z)));
    sx = q[0], sy = q[1], sz = q[2];
#else
    sx = -d.x / d.z, sy = -d.y / d.z, sz = 1.0f / d.z;
#endif
  }
};

/// intersect_triangle(ray, p0, p1, p2, hit) with ray.tmax = tmax, for a ray prepared as `r`: the same
/// answer and, on a hit, bit-identical t, b0, b1, b2. The operations below are Part 1's, in
/// Part 1's order; change one only together with the other (the framework's accel tests compare
/// them on millions of rays). On a hit, *t_error (when given) is Part 1's bound on how far t is
/// from the exact distance.
inline bool intersect_sheared_triangle(const ShearedRay& r, float tmax, const glm::vec3& p0,
                                       const glm::vec3& p1, const glm::vec3& p2, TriangleHit* hit,
                                       float* t_error = nullptr) {
  if (r.degenerate) return false;
  glm::vec3 a(p0[r.kx] - r.o[r.kx], p0[r.ky] - r.o[r.ky], p0[r.kz] - r.o[r.kz]);
  glm::vec3 b(p1[r.kx] - r.o[r.kx], p1[r.ky] - r.o[r.ky], p1[r.kz] - r.o[r.kz]);
  glm::vec3 c(p2[r.kx] - r.o[r.kx], p2[r.ky] - r.o[r.ky], p2[r.kz] - r.o[r.kz]);
  a.x += r.sx * a.z, a.y += r.sy * a.z;
  b.x += r.sx * b.z, b.y += r.sy * b.z;
  c.x += r.sx * c.z, c.y += r.sy * c.z;

  float e0 = b.x * c.y - b.y * c.x;
  float e1 = c.x * a.y - c.y * a.x;
  float e2 = a.x * b.y - a.y * b.x;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
    e0 = float(double(b.x) * c.y - double(b.y) * c.x);
    e1 = float(double(c.x) * a.y - double(c.y) * a.x);
    e2 = float(double(a.x) * b.y - double(a.y) * b.x);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;

  a.z *= r.sz, b.z *= r.sz, c.z *= r.sz;
  const float t_scaled = e0 * a.z + e1 * b.z + e2 * c.z;
  if (det > 0 ? (t_scaled <= r.tmin * det || t_scaled >= tmax * det)
              : (t_scaled >= r.tmin * det || t_scaled <= tmax * det))
    return false;

  const float inv_det = 1.0f / det;
  const float t = t_scaled * inv_det;
  if (!(t > r.tmin && t < tmax)) return false;

  const float max_z = std::max({std::abs(a.z), std::abs(b.z), std::abs(c.z)});
  const float max_x = std::max({std::abs(a.x), std::abs(b.x), std::abs(c.x)});
  const float max_y = std::max({std::abs(a.y), std::abs(b.y), std::abs(c.y)});
  const float err_z = gamma(3) * max_z;
  const float err_x = gamma(5) * (max_x + max_z);
  const float err_y = gamma(5) * (max_y + max_z);
  const float err_e = 2.0f * (gamma(2) * max_x * max_y + err_y * max_x + err_x * max_y);
  const float max_e = std::max({std::abs(e0), std::abs(e1), std::abs(e2)});
  const float err_t =
      3.0f * (gamma(3) * max_e * max_z + err_e * max_z + err_z * max_e) * std::abs(inv_det);
  if (t <= err_t) return false;

  if (t_error) *t_error = err_t;
  hit->t = t;
  hit->b0 = e0 * inv_det;
  hit->b1 = e1 * inv_det;
  hit->b2 = e2 * inv_det;
  return true;
}

}  // namespace pt
