// Warps: maps from uniform points of the unit square to points and directions with known densities.
//
// Every warp has the density it produces next to it, so a caller never divides by a density that
// belongs to another distribution; the chi-square tests check each pair against the other.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pt {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;

/// sqrt that treats a slightly negative argument (rounding) as zero instead of returning NaN.
inline float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }

/// Uniform point of the unit disk; the concentric map (Shirley and Chiu 1997) keeps strata
/// compact, unlike the polar map that squeezes them at the centre.
inline glm::vec2 square_to_uniform_disk(glm::vec2 u) {
  glm::vec2 o = 2.0f * u - glm::vec2(1.0f);
  if (o.x == 0.0f && o.y == 0.0f) return glm::vec2(0.0f);
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = (kPi / 4.0f) * (o.y / o.x);
  } else {
    r = o.y;
    theta = kPi / 2.0f - (kPi / 4.0f) * (o.x / o.y);
  }
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

/// Uniform direction of the hemisphere z >= 0 (density 1/2π per steradian).
inline glm::vec3 square_to_uniform_hemisphere(glm::vec2 u) {
  float z = u.x;
  float r = safe_sqrt(1.0f - z * z);
  float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniform_hemisphere_pdf(const glm::vec3& w) { return w.z >= 0.0f ? kInv2Pi : 0.0f; }

/// Cosine-weighted direction of the hemisphere z >= 0 (density cosθ/π): a uniform disk point
/// lifted onto the hemisphere (Malley's method).
inline glm::vec3 square_to_cosine_hemisphere(glm::vec2 u) {
  glm::vec2 d = square_to_uniform_disk(u);
  return {d.x, d.y, safe_sqrt(1.0f - glm::dot(d, d))};
}
inline float cosine_hemisphere_pdf(const glm::vec3& w) { return w.z > 0.0f ? w.z * kInvPi : 0.0f; }

/// Uniform direction of the whole sphere (density 1/4π).
inline glm::vec3 square_to_uniform_sphere(glm::vec2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = safe_sqrt(1.0f - z * z);
  float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniform_sphere_pdf() { return kInv4Pi; }

/// Uniform direction of the cone about +z whose half-angle θmax has 1 − cosθmax =
/// `one_minus_cos_max` (density 1/(2π(1 − cosθmax))). The cone is given by 1 − cosθmax rather
/// than cosθmax because a narrow cone (a small, far sphere light) has a cosθmax that rounds to 1,
/// while 1 − cosθmax computed as sin²θ/(1 + cosθ) keeps its digits: its density stays finite
/// and right.
inline glm::vec3 square_to_uniform_cone(glm::vec2 u, float one_minus_cos_max) {
  float z = 1.0f - u.x * one_minus_cos_max;
  float r = safe_sqrt(1.0f - z * z);
  float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniform_cone_pdf(float one_minus_cos_max) {
  return 1.0f / (2.0f * kPi * one_minus_cos_max);
}

/// Barycentric coordinates (b0, b1, b2) of a uniform point of a triangle, by the square-root map
/// (Turk 1990; pbrt), which keeps the fold-free mapping of the square.
inline glm::vec3 square_to_uniform_triangle(glm::vec2 u) {
  float su = std::sqrt(u.x);
  float b0 = 1.0f - su, b1 = u.y * su;
  return {b0, b1, 1.0f - b0 - b1};
}

/// Converts a density per unit area at a point seen from distance `distance` under cosine
/// `cos_at_point` (between its normal and the direction back to the viewer) into a density per
/// steradian. Zero when the point is seen edge-on, where the density per steradian is unbounded
/// and the sample carries no light anyway.
inline float area_to_solid_angle_pdf(float pdf_area, float distance, float cos_at_point) {
  float c = std::abs(cos_at_point);
  if (!(c > 0.0f)) return 0.0f;
  return pdf_area * distance * distance / c;
}

}  // namespace pt
