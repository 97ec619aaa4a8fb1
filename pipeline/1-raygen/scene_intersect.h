// Given code on Part 1: a primitive of a Scene intersected by the student's tests, with its full
// SurfaceHit (point, error bound, normals, material), and every primitive tested one by one
// (brute force, the yardstick the BVH is checked by).
#pragma once

#include <cstdint>

#include "framework/geometry/ray_query.h"
#include "framework/scene/scene.h"

namespace pt {

/// Intersects primitive `primitive` of `scene` (triangle or sphere) with `ray`; on a hit with
/// tmin < t < tmax fills *hit completely: point, its error bound, normals, material.
bool intersect_primitive(const Scene& scene, uint32_t primitive, const Ray& ray, SurfaceHit* hit);

/// The SurfaceHit of triangle `primitive` where intersect_triangle already reported `th` for some
/// ray: what intersect_primitive fills after its own triangle test, for a caller that found the
/// hit itself with bit-identical t and barycentrics. False for a triangle whose corners are
/// collinear in float (no normal to shade by), as intersect_primitive refuses it.
bool triangle_surface_hit(const Scene& scene, uint32_t primitive, const TriangleHit& th,
                          SurfaceHit* hit);

/// The same SurfaceHit, bit for bit, for a caller that already holds the triangle's corners and
/// vertex indices (a wide tree's leaf packet, just read by its test): only the normals and the
/// material are loaded, and nothing waits on the triangle's record for where its corners are.
bool triangle_surface_hit(const Scene& scene, uint32_t primitive, const TriangleHit& th,
                          const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                          const uint32_t vertex[3], SurfaceHit* hit);

/// Whether primitive `primitive` blocks `ray` somewhere in (tmin, tmax).
bool primitive_occludes(const Scene& scene, uint32_t primitive, const Ray& ray);

/// Every primitive tested for every ray: slow, simple, and the yardstick the BVH is checked by.
class BruteForce final : public RayQuery {
 public:
  explicit BruteForce(const Scene& scene) : scene_(scene) {}
  bool intersect(const Ray& ray, SurfaceHit* hit) const override;
  bool occluded(const Ray& ray) const override;

 private:
  const Scene& scene_;
};

}  // namespace pt
