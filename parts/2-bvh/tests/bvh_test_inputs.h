// Inputs the BVH tests share (Part 2's and the wide tree's): the degenerate scenes
// that break naive builds and traversals, and the normals view rendered through any ray query.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/render/pixel_stats.h"
#include "framework/sampling/rng.h"
#include "framework/scene/scene.h"
#include "parts/1-raygen/pixel_loop.h"

namespace pt::test {

/// Appends triangle (a, b, c) of material 0 with corners of its own.
inline void add_triangle(Scene* s, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const uint32_t base = uint32_t(s->positions.size());
  for (const glm::vec3& p : {a, b, c}) s->positions.push_back(p);
  s->triangles.push_back(Triangle{{base, base + 1, base + 2}, 0});
}

/// 300 triangles and 20 nested spheres whose boxes are all centred on the origin: no plane
/// separates any two of them.
inline Scene centroids_all_equal() {
  Scene s;
  Rng rng(5);
  for (int i = 0; i < 300; ++i) {
    const float a = 0.1f + rng.next_float(), b = 0.1f + rng.next_float(), z = rng.next_float();
    add_triangle(&s, {-a, -b, z}, {a, -b, -z}, {0.0f, b, z});
  }
  for (int i = 1; i <= 20; ++i) s.spheres.push_back(Sphere{glm::vec3(0), 0.1f * float(i), 0});
  return s;
}

/// A 20x20 grid of triangle pairs in the plane z = 0: every box has zero thickness.
inline Scene flat_grid() {
  Scene s;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const glm::vec3 p(float(i), float(j), 0.0f);
      add_triangle(&s, p, p + glm::vec3(1, 0, 0), p + glm::vec3(1, 1, 0));
      add_triangle(&s, p, p + glm::vec3(1, 1, 0), p + glm::vec3(0, 1, 0));
    }
  return s;
}

/// Rays for flat_grid(): half run inside its plane (the slab test divides 0 by 0), half come
/// straight down onto its lines and corners.
inline std::vector<Ray> rays_at_flat_grid(uint64_t seed) {
  std::vector<Ray> rays;
  Rng rng(seed);
  for (int i = 0; i < 2000; ++i) {
    Ray r;
    r.o = glm::vec3(20.0f * rng.next_float(), 20.0f * rng.next_float(), 0.0f);
    const float phi = 2.0f * glm::pi<float>() * rng.next_float();
    r.d = glm::vec3(std::cos(phi), std::sin(phi), 0.0f);
    rays.push_back(r);
    r.o.z = 1.0f, r.d = glm::vec3(0, 0, -1);
    r.o.x = float(int(r.o.x)), r.o.y = rng.next_float() < 0.5f ? float(int(r.o.y)) : r.o.y;
    rays.push_back(r);
  }
  return rays;
}

/// `n` copies of one triangle: every ray through it ties, and the lowest index must win.
inline Scene duplicate_triangles(int n) {
  Scene s;
  for (int i = 0; i < n; ++i) add_triangle(&s, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  return s;
}

/// The normals view of `scene` at w x h, `spp` jittered samples a pixel, each pixel's random
/// numbers from (seed, pixel): the same seed gives the same rays whatever answers them.
inline std::vector<glm::dvec3> render_normals(const Scene& scene, const RayQuery& query, int w,
                                              int h, int spp, uint64_t seed) {
  std::vector<glm::dvec3> image;
  const RadianceFn radiance = [&](const Ray& ray, Rng&) {
    SurfaceHit hit;
    return query.intersect(ray, &hit) ? hit.n * 0.5f + glm::vec3(0.5f) : glm::vec3(0.0f);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Rng rng(seed, uint64_t(y) * uint64_t(w) + uint64_t(x));
      PixelStats stats;
      estimate_pixel(scene.camera, PixelRef{x, y, w, h}, spp, rng, radiance, &stats);
      image.push_back(stats.mean);
    }
  return image;
}

}  // namespace pt::test
