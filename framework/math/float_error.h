// Floating-point error bounds: the tools that make intersections robust by construction.
//
// Every float operation rounds to within a relative (1 ± u) of the exact result, u = 2^-24.
// A chain of n operations stays within gamma(n) = n·u / (1 − n·u) (Higham 2002; pbrt-v4, ch. 6).
// Hit points carry such a bound, and a ray leaving a surface starts just outside that box, so it
// cannot hit the surface it leaves: no tuned epsilon anywhere.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace pt {

inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;

/// Bound on the relative error of n chained float operations.
constexpr float gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

inline uint32_t float_to_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}
inline float bits_to_float(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

/// The next float above v (v itself for +inf); -0 and +0 both step to the smallest denormal.
inline float next_float_up(float v) {
  if (std::isinf(v) && v > 0.0f) return v;
  if (v == -0.0f) v = 0.0f;
  uint32_t ui = float_to_bits(v);
  ui = (v >= 0) ? ui + 1 : ui - 1;
  return bits_to_float(ui);
}

/// The next float below v (v itself for -inf).
inline float next_float_down(float v) {
  if (std::isinf(v) && v < 0.0f) return v;
  if (v == 0.0f) v = -0.0f;
  uint32_t ui = float_to_bits(v);
  ui = (v > 0) ? ui - 1 : ui + 1;
  return bits_to_float(ui);
}

/// Origin for a ray that leaves the surface at p (absolute error p_error per axis) towards w.
/// The point is pushed along the geometric normal n, to the side w points to, just past the
/// error box, then rounded away from p so the rounding of the push cannot pull it back inside.
inline glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& p_error,
                                   const glm::vec3& n, const glm::vec3& w) {
  float d = glm::dot(glm::abs(n), p_error);
  glm::vec3 offset = d * n;
  if (glm::dot(w, n) < 0) offset = -offset;
  glm::vec3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0)
      po[i] = next_float_up(po[i]);
    else if (offset[i] < 0)
      po[i] = next_float_down(po[i]);
  }
  return po;
}

}  // namespace pt
