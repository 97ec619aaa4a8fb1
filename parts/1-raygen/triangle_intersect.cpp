// Part 1, step 3 (triangle): intersect_triangle, interpolate_normal; step 5 (watertight): the
// same intersect_triangle, watertight and above its own t error bound.
#include "parts/1-raygen/triangle_intersect.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "framework/math/float_error.h"
#include "framework/student/todo.h"

namespace pt {

bool intersect_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                        const glm::vec3& p2, TriangleHit* hit) {
  // BEGIN SOLUTION
  // In the ray's own frame (origin at 0, direction +z) the question is 2D: is (0,0) inside the
  // projected triangle? Two triangles sharing an edge compute bit-identical edge functions for it
  // (same corners, same operations), with opposite signs, so no ray slips between them.
  glm::vec3 a = p0 - ray.o, b = p1 - ray.o, c = p2 - ray.o;

  // Make the direction's largest component z, so the shear below never divides by ~0.
  const glm::vec3 ad = glm::abs(ray.d);
  const int kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  if (ray.d[kz] == 0.0f) return false;  // a zero direction meets nothing
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  const glm::vec3 d(ray.d[kx], ray.d[ky], ray.d[kz]);
  a = glm::vec3(a[kx], a[ky], a[kz]);
  b = glm::vec3(b[kx], b[ky], b[kz]);
  c = glm::vec3(c[kx], c[ky], c[kz]);

  // Shear x and y so the direction becomes (0, 0, 1); z is scaled only once we know it is needed.
  const float sx = -d.x / d.z, sy = -d.y / d.z, sz = 1.0f / d.z;
  a.x += sx * a.z, a.y += sy * a.z;
  b.x += sx * b.z, b.y += sy * b.z;
  c.x += sx * c.z, c.y += sy * c.z;

  // Twice the signed area each edge spans with the origin; e0 faces p0 (it is the edge p1-p2).
  float e0 = b.x * c.y - b.y * c.x;
  float e1 = c.x * a.y - c.y * a.x;
  float e2 = a.x * b.y - a.y * b.x;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
    // Exactly on an edge in float: products of floats are exact in double, so its sign is right.
    e0 = float(double(b.x) * c.y - double(b.y) * c.x);
    e1 = float(double(c.x) * a.y - double(c.y) * a.x);
    e2 = float(double(a.x) * b.y - double(a.y) * b.x);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;  // seen edge-on, or a degenerate triangle

  // t·det, compared with the interval scaled by det, so a miss costs no division.
  a.z *= sz, b.z *= sz, c.z *= sz;
  const float t_scaled = e0 * a.z + e1 * b.z + e2 * c.z;
  if (det > 0 ? (t_scaled <= ray.tmin * det || t_scaled >= ray.tmax * det)
              : (t_scaled >= ray.tmin * det || t_scaled <= ray.tmax * det))
    return false;

  const float inv_det = 1.0f / det;
  const float t = t_scaled * inv_det;
  if (!(t > ray.tmin && t < ray.tmax)) return false;

  // A hit is in front of the origin only if t beats its own rounding error (pbrt-v4, 6.8.7):
  // bounds on the error of the sheared z, x, y, of the edge functions, then of t.
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

  hit->t = t;
  hit->b0 = e0 * inv_det;
  hit->b1 = e1 * inv_det;
  hit->b2 = e2 * inv_det;
  return true;
  // END SOLUTION
  // STUDENT: return whether the ray meets the triangle (p0, p1, p2) at some tmin < t < tmax, from
  // either side, and on a hit fill *hit with t and the barycentric coordinates (b0 is p0's
  // weight; the three add up to 1). A triangle with two equal corners is never hit. Step 3 checks
  // the answers against exact arithmetic. Step 5 (watertight) holds the same function to four
  // more rules: a ray through a shared edge or vertex hits one of the triangles; an edge function
  // that is exactly zero in float is recomputed in double, so a ray a hair beside an edge lands on
  // the side exact arithmetic gives; a hit counts only where t exceeds its own rounding error
  // bound, so a ray cannot hit the triangle it leaves; and no fixed epsilon, on the determinant or
  // on t (grazing rays, tiny triangles, hits at t down to 1e-7 are hits). docs/handout/part1.md
  // explains why and where to read.
  PT_STUDENT_TODO("part 1", "intersect_triangle");
  (void)ray, (void)p0, (void)p1, (void)p2, (void)hit;
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit& hit, const glm::vec3& n0, const glm::vec3& n1,
                             const glm::vec3& n2) {
  // BEGIN SOLUTION
  return glm::normalize(hit.b0 * n0 + hit.b1 * n1 + hit.b2 * n2);
  // END SOLUTION
  // STUDENT: return the unit shading normal at the hit: the corners' normals weighted by the hit's
  // barycentric coordinates (n0 by b0).
  PT_STUDENT_TODO("part 1", "interpolate_normal");
  (void)hit, (void)n1, (void)n2;
  return n0;
}

}  // namespace pt
