// Part 1, step 3 (triangle): where a ray meets a triangle, and the shading normal at the hit;
// step 5 (watertight): the same test, watertight and above its own t error bound.
#pragma once

#include <glm/vec3.hpp>

#include "framework/geometry/surface_hit.h"
#include "framework/math/ray.h"

namespace pt {

/// Step 3 (triangle) and step 5 (watertight).
/// Whether `ray` meets triangle (p0, p1, p2) at some ray.tmin < t < ray.tmax; on a hit, fills
/// *hit with t and the barycentric coordinates (b0 for p0; the three add up to 1). Watertight: a
/// ray through an edge or a vertex shared by two triangles hits at least one of them, whatever the
/// rounding (Woop, Benthin and Wald 2013), and an edge function that is exactly zero in float is
/// recomputed in double. Both sides of the triangle count. A triangle with two equal corners is
/// never hit. A hit is only reported where t exceeds its own rounding error bound (pbrt-v4,
/// 6.8.7), so a ray cannot hit the triangle it starts on because of rounding alone; no fixed
/// epsilon on the determinant or on t.
bool intersect_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                        const glm::vec3& p2, TriangleHit* hit);

/// The shading normal at a hit: the corners' normals weighted by the hit's barycentric
/// coordinates, normalised.
glm::vec3 interpolate_normal(const TriangleHit& hit, const glm::vec3& n0, const glm::vec3& n1,
                             const glm::vec3& n2);

}  // namespace pt
