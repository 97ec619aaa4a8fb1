// What the lighting tests (Parts 3 and 4, the framework's lights) share: a scene with its own ray
// query, lights and LightingContext, and a radiance estimator sampled many times.
#pragma once

#include <functional>
#include <vector>

#include "framework/lights/light_set.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/shading/lighting_context.h"
#include "framework/testing/test_scenes.h"

namespace pt::test {

/// A scene with its query and lights, and a context over them with the given settings.
struct Rig {
  explicit Rig(const Scene& s) : scene(s), query(scene), lights(scene), ctx{scene, query, lights} {}
  Scene scene;
  DoubleQuery query;
  LightSet lights;
  LightingContext ctx;
};

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
