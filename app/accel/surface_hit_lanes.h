// The wide tree's full hit: pipeline/1-raygen's triangle_surface_hit (corners given) in SIMD
// lanes, the same operations in the same order, so the same bits (its test holds it to them).
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "app/fast/vec3_lanes.h"
#include "framework/geometry/surface_hit.h"
#include "framework/math/float_error.h"
#include "framework/scene/scene.h"
#include "parts/1-raygen/triangle_intersect.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt {

/// triangle_surface_hit(scene, primitive, th, p0, p1, p2, vertex, hit), bit for bit.
inline bool triangle_surface_hit_in_lanes(const Scene& scene, uint32_t primitive,
                                          const TriangleHit& th, const glm::vec3& p0,
                                          const glm::vec3& p1, const glm::vec3& p2,
                                          const uint32_t vertex[3], SurfaceHit* hit) {
#if PT_SSE2
  // Every full hit the wide tree reports comes here.
  using namespace lanes;
  const V3 c0 = load(p0), c1 = load(p1), c2 = load(p2);
  const V3 cross = lanes::cross(sub(c1, c0), sub(c2, c0));
  const float len = std::sqrt(lanes::dot(cross, cross));
  if (!(len > 0.0f) || !std::isfinite(len)) return false;
  V3 ng = div(cross, splat(len));
  const V3 a = mul(splat(th.b0), c0), b = mul(splat(th.b1), c1), c = mul(splat(th.b2), c2);
  hit->p = to_vec3(add(add(a, b), c));
  hit->p_error = to_vec3(mul(splat(gamma(7)), add(add(glm_abs(a), glm_abs(b)), glm_abs(c))));
  V3 n = ng;
  if (!scene.normals.empty()) {
    const glm::vec3 ns = interpolate_normal(th, scene.normals[vertex[0]], scene.normals[vertex[1]],
                                            scene.normals[vertex[2]]);
    if (std::isfinite(ns.x) && std::isfinite(ns.y) && std::isfinite(ns.z) && glm::dot(ns, ns) > 0.0f)
      n = load(ns);
  }
  if (lanes::dot(ng, n) < 0.0f) ng = neg(ng);
  hit->t = th.t;
  hit->ng = to_vec3(ng);
  hit->n = to_vec3(n);
  hit->primitive = primitive;
  hit->material = scene.triangles[primitive].material;
  return true;
#else
  return triangle_surface_hit(scene, primitive, th, p0, p1, p2, vertex, hit);
#endif
}

}  // namespace pt
