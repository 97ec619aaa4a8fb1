// Not needed for the assignment.
// What the lighting tests (Parts 3 and 4, the framework's lights) share: a scene with its own ray
// query, lights and LightingContext, and a radiance estimator sampled many times.
#pragma once

#include <cmath>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "framework/bsdf/bsdf.h"
#include "framework/geometry/surface_hit.h"
#include "framework/lights/light_set.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/shading/lighting_context.h"
#include "framework/testing/test_scenes.h"

namespace pt::test {

/// A scene with its query and lights, and a context over them with the given settings.
struct Rig {
  explicit Rig(const Scene& s)
      : scene(s), query(scene), lights(scene), ctx{scene, query, lights} {}
  Scene scene;
  DoubleQuery query;
  LightSet lights;
  LightingContext ctx;
};

/// The rig's own Lambertian reflector: f = ρ/π above the surface, zero below, sampled uniformly
/// over the hemisphere (density 1/2π: correct, and deliberately not the cosine sampling Part 3's
/// DiffuseBsdf is asked for, so that it is no answer to copy). Lighting tests of the steps after
/// part3.step1.diffuse_bsdf shade with it (ShadedByRig), so a bug in the student's BSDF costs
/// that step only.
class RigLambertian final : public Bsdf {
 public:
  explicit RigLambertian(const glm::vec3& albedo = glm::vec3(0.0f)) : albedo_(albedo) {}
  glm::vec3 f(const glm::vec3&, const glm::vec3& wi) const override {
    return wi.z > 0.0f ? albedo_ * kInvPi : glm::vec3(0.0f);
  }
  glm::vec3 sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* p) const override {
    *wi = square_to_uniform_hemisphere(u);
    *p = pdf(wo, *wi);
    return f(wo, *wi);
  }
  float pdf(const glm::vec3&, const glm::vec3& wi) const override {
    return wi.z > 0.0f ? kInv2Pi : 0.0f;
  }
  bool is_delta() const override { return false; }

 private:
  glm::vec3 albedo_;
};

/// A shading point (`Point`, Part 3's ShadingPoint) whose diffuse BSDF (`Diffuse`, the student's
/// class) is replaced by the rig's RigLambertian of the same albedo; mirrors, glass and
/// emitters keep the framework's BSDFs. `point` is what the step's function is handed.
template <class Point, class Diffuse>
class ShadedByRig {
 public:
  ShadedByRig(const Scene& scene, const Ray& ray, const SurfaceHit& hit) : point(scene, ray, hit) {
    if (dynamic_cast<const Diffuse*>(point.bsdf) != nullptr) {
      // The albedo the shading point gave its diffuse BSDF (the default material's where the
      // hit names none).
      lambertian_ = RigLambertian(point.hit.material < scene.materials.size()
                                      ? scene.materials[point.hit.material].albedo
                                      : Material{}.albedo);
      point.bsdf = &lambertian_;
    }
  }
  ShadedByRig(const ShadedByRig&) = delete;
  ShadedByRig& operator=(const ShadedByRig&) = delete;

  Point point;

 private:
  RigLambertian lambertian_;
};

/// A ratio of an estimate to its exact value that points at one cause, and that cause.
struct RatioCause {
  double ratio;
  const char* cause;
};

/// The ratio of a failing estimate's mean to the exact value, in words, with the cause of the
/// first of `causes` whose ratio it matches within 4% (the tests' samples leave well under 1%
/// of noise): " (0.5x the exact value: CAUSE)". A ratio no listed cause explains gets none, and
/// so does a cause whose ratio is near 0 or 1 (it cannot be told from nothing, or from right).
inline std::string ratio_hint(double mean, double expected,
                              std::initializer_list<RatioCause> causes) {
  std::ostringstream o;
  if (!(expected != 0.0) || !std::isfinite(mean)) return "";
  const double r = mean / expected;
  if (r == 0.0) return " (0: no light at all came back)";
  o.precision(3);
  o << " (" << r << "x the exact value";
  for (const RatioCause& c : causes)
    if (c.ratio > 0.04 && std::abs(c.ratio - 1.0) > 0.04 && std::abs(r / c.ratio - 1.0) < 0.04) {
      o << ": " << c.cause;
      break;
    }
  o << ")";
  return o.str();
}

using Estimator = std::function<glm::vec3(const Ray&, Rng&)>;

/// n samples of channel `channel` of `estimate` for rays from `make_ray`, each with its own
/// seeded stream.
inline std::vector<double> sample_values(const Estimator& estimate,
                                         const std::function<Ray(Rng&)>& make_ray, int n,
                                         uint64_t seed, int channel = 0) {
  std::vector<double> xs;
  xs.reserve(n);
  Rng rng(seed, 17);
  for (int i = 0; i < n; ++i) {
    Ray r = make_ray(rng);
    xs.push_back(estimate(r, rng)[channel]);
  }
  return xs;
}

/// A ray from a random point at distance 3 from the origin aimed near the origin, so that it
/// hits a unit sphere there.
inline Ray ray_at_unit_sphere(Rng& rng) {
  glm::vec3 from = 3.0f * square_to_uniform_sphere(rng.next_2d());
  glm::vec3 to = 0.5f * (square_to_uniform_sphere(rng.next_2d()));
  Ray r;
  r.o = from;
  r.d = glm::normalize(to - from);
  return r;
}

/// A ray from near the origin in a uniform direction (for the inside of an enclosure).
inline Ray ray_from_inside(Rng& rng) {
  Ray r;
  r.o = 0.3f * square_to_uniform_sphere(rng.next_2d());
  r.d = square_to_uniform_sphere(rng.next_2d());
  return r;
}

}  // namespace pt::test
