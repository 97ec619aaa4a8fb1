// Not needed for the assignment.
// Hand-made scenes for the lighting tests, and a ray query of their own that does not depend on
// Part 1 or 2: lighting is graded on its own, whatever state the student's intersection code is in.
#pragma once

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/math/float_error.h"
#include "framework/render/pixel_stats.h"
#include "framework/scene/light.h"
#include "framework/scene/scene.h"
#include "framework/testing/observed_counters.h"
#include "framework/stats/distributions.h"

namespace pt::test {

/// The lighting tests' own ray query: every primitive of the scene, none skipped, in a form
/// that is deliberately not the one Part 1 asks for, so that it is no answer to copy. Whether a
/// ray meets a triangle is CGAL's exact predicate (the ray against the triangle, decided without
/// rounding) and t follows from the triangle's plane in double; a sphere's roots are found by
/// bisection in double of the squared distance to its centre along the ray. The hit point is
/// within rounding of the surface and p_error bounds that rounding (a few ulps of |p|), as the
/// shadow rays need. Where the scene has vertex normals the shading normal is the normal of the
/// corner nearest the hit: a crude stand-in, enough for tests that need a shading normal apart
/// from ng (broken ones included), not an interpolation. Defined in double_query.cpp, the one
/// file that compiles CGAL.
class DoubleQuery final : public RayQuery {
 public:
  explicit DoubleQuery(const Scene& scene) : s_(scene) {
    observe_counter(&intersect_calls);
    observe_counter(&occluded_calls);
  }
  ~DoubleQuery() override {
    forget_counter(&intersect_calls);
    forget_counter(&occluded_calls);
  }
  DoubleQuery(const DoubleQuery&) = delete;
  DoubleQuery& operator=(const DoubleQuery&) = delete;
  mutable long intersect_calls = 0, occluded_calls = 0;

  bool intersect(const Ray& ray, SurfaceHit* hit) const override {
    ++intersect_calls;
    return nearest(ray, hit, false);
  }
  bool occluded(const Ray& ray) const override {
    ++occluded_calls;
    SurfaceHit h;
    return nearest(ray, &h, true);
  }

 private:
  bool nearest(const Ray& ray, SurfaceHit* hit, bool any) const;
  const Scene& s_;
};

inline uint32_t add_material(Scene& s, const glm::vec3& albedo, const glm::vec3& emission = {},
                             MaterialKind kind = MaterialKind::diffuse) {
  Material m;
  m.kind = kind;
  m.albedo = albedo;
  m.emission = emission;
  s.materials.push_back(m);
  return uint32_t(s.materials.size() - 1);
}

inline void add_triangle(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
  uint32_t base = uint32_t(s.positions.size());
  s.positions.insert(s.positions.end(), {a, b, c});
  s.triangles.push_back(Triangle{{base, base + 1, base + 2}, material});
}

/// Quad a, b, c, d (in order around it) as two triangles.
inline void add_quad(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                     uint32_t material) {
  add_triangle(s, a, b, c, material);
  add_triangle(s, a, c, d, material);
}

/// The closed cube [−1, 1]^3, every face of `material` (12 triangles).
inline void add_closed_cube(Scene& s, uint32_t material) {
  glm::vec3 v[8];
  for (int i = 0; i < 8; ++i) v[i] = glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  add_quad(s, v[0], v[1], v[3], v[2], material);  // z = -1
  add_quad(s, v[4], v[6], v[7], v[5], material);  // z = +1
  add_quad(s, v[0], v[4], v[5], v[1], material);  // y = -1
  add_quad(s, v[2], v[3], v[7], v[6], material);  // y = +1
  add_quad(s, v[0], v[2], v[6], v[4], material);  // x = -1
  add_quad(s, v[1], v[5], v[7], v[3], material);  // x = +1
}

inline Light ambient_light(const glm::vec3& radiance) {
  Light l;
  l.kind = LightKind::ambient;
  l.radiance = radiance;
  return l;
}

/// Form factor from a point to a rectangle parallel to the plane it lies in, facing it, at height
/// h: the rectangle spans [x0, x1] × [y0, y1] measured from the point's foot. A diffuse surface
/// of albedo ρ under a one-sided emitter of radiance L there reflects ρ·L·F (its irradiance is
/// π·L·F). By corners: the form factor of [0, a] × [0, b] is
/// (1/2π)·[A/√(1+A²)·atan(B/√(1+A²)) + B/√(1+B²)·atan(A/√(1+B²))], A = a/h, B = b/h, signed by
/// the corner's quadrant and summed with signs over the four corners.
inline double rectangle_form_factor(double x0, double x1, double y0, double y1, double h) {
  auto corner = [h](double x, double y) {
    const double a = std::abs(x) / h, b = std::abs(y) / h;
    const double ra = std::sqrt(1 + a * a), rb = std::sqrt(1 + b * b);
    const double f = (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb)) / (2 * M_PI);
    return (x < 0) == (y < 0) ? f : -f;
  };
  return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

/// A square area light facing down (-z) at height `z`, centred over the origin, 2·half across:
/// its panel (a quad of `material`, which should emit) and the scene light that agrees with it,
/// so that light sampling samples the very panel a ray can hit.
inline void add_square_ceiling_light(Scene& s, float half, float z, const glm::vec3& radiance,
                                     uint32_t material) {
  add_quad(s, {-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}, material);
  Light l;
  l.kind = LightKind::area;
  l.radiance = radiance;
  l.position = glm::vec3(0.0f, 0.0f, z);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  l.edge_u = glm::vec3(2.0f * half, 0.0f, 0.0f);
  l.edge_v = glm::vec3(0.0f, 2.0f * half, 0.0f);
  s.lights.push_back(l);
}

/// CBcoil's situation in miniature: a floor (albedo 0.5, z = 0) under a panel of emission 10,
/// 0.8 × 0.6 at z = 0.5, that lies on an area light of radiance 5 turned the other way round
/// (0.6 × 0.8), shining down. By the emitter rule the light's rectangle with its radiance lights
/// the floor, and the camera sees the panel's shape glowing with the light's radiance.
struct DisagreeingPanel {
  static constexpr float kHeight = 0.5f, kPanelX = 0.4f, kPanelY = 0.3f;  // half sizes
  static constexpr float kLightRadiance = 5.0f, kPanelEmission = 10.0f, kFloorAlbedo = 0.5f;
  /// Direct light the floor reflects at (x, y): ρ·L·F over the light's own rectangle (kPanelY
  /// across x, kPanelX across y), which lights the scene whatever the panel's shape.
  static double floor_radiance(double x, double y) {
    return kFloorAlbedo * kLightRadiance *
           rectangle_form_factor(-kPanelY - x, kPanelY - x, -kPanelX - y, kPanelX - y, kHeight);
  }
};
inline Scene disagreeing_panel_scene(MaterialKind floor_kind = MaterialKind::diffuse) {
  Scene s;
  using P = DisagreeingPanel;
  const uint32_t floor =
      add_material(s, glm::vec3(P::kFloorAlbedo), glm::vec3(0.0f), floor_kind);
  const uint32_t panel = add_material(s, glm::vec3(0.8f), glm::vec3(P::kPanelEmission),
                                      MaterialKind::emission);
  add_quad(s, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}, floor);
  add_quad(s, {-P::kPanelX, -P::kPanelY, P::kHeight}, {P::kPanelX, -P::kPanelY, P::kHeight},
           {P::kPanelX, P::kPanelY, P::kHeight}, {-P::kPanelX, P::kPanelY, P::kHeight}, panel);
  Light l;
  l.name = "Light";
  l.kind = LightKind::area;
  l.radiance = glm::vec3(P::kLightRadiance);
  l.position = glm::vec3(0.0f, 0.0f, P::kHeight);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  l.edge_u = glm::vec3(2 * P::kPanelY, 0.0f, 0.0f);  // 0.6 across x
  l.edge_v = glm::vec3(0.0f, 2 * P::kPanelX, 0.0f);  // 0.8 across y
  s.lights.push_back(l);
  return s;
}

/// Two-sided t-test of a sample mean against a known value: true when the difference is within
/// what chance explains at significance alpha (Student's t with n − 1 degrees of freedom).
/// Non-finite statistics never pass.
struct MeanCheck {
  bool pass = false;
  double mean = 0, stderr_ = 0, t = 0;
};
inline MeanCheck t_test_mean(const std::vector<double>& xs, double expected, double alpha) {
  MeanCheck r;
  double n = double(xs.size()), m = 0, m2 = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    double delta = xs[i] - m;
    m += delta / double(i + 1);
    m2 += delta * (xs[i] - m);
  }
  r.mean = m;
  r.stderr_ = std::sqrt(m2 / (n - 1) / n);
  if (!std::isfinite(r.mean) || !std::isfinite(r.stderr_)) return r;
  if (r.stderr_ == 0.0) {
    r.pass = std::abs(m - expected) <= 1e-5 * std::max(1.0, std::abs(expected));
    return r;
  }
  r.t = (m - expected) / r.stderr_;
  const double critical = students_t_two_sided_critical(n - 1, alpha);
  r.pass = std::abs(r.t) <= critical;
  return r;
}

}  // namespace pt::test
