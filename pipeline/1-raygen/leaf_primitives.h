// Given code on Part 1: the primitives of a tree's leaves in leaf order, and the two tests a
// traversal runs on one leaf's run of them (nearest hit, any hit), built on Part 1's intersection
// tests. Free of any tree type, so Part 2's traversal calls them from below.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "framework/math/ray.h"
#include "framework/scene/scene.h"
#include "pipeline/1-raygen/nearest_hit_query.h"

namespace pt {

/// A tree's primitive indices in leaf order, each triangle with a copy of its corners
/// (bit-identical to the scene's), so a leaf's triangles are read from one contiguous block.
struct LeafPrimitives {
  /// The corners of a triangle in leaf order (unused for a sphere's entry).
  struct TriangleCorners {
    glm::vec3 p0, p1, p2;
  };
  std::vector<uint32_t> order;           ///< scene primitive of each leaf-order entry
  std::vector<TriangleCorners> corners;  ///< corners of entry i's triangle

  /// `order` for `scene`, with the corner copies made from it.
  LeafPrimitives(const Scene& scene, std::vector<uint32_t> order);
  LeafPrimitives() = default;
};

/// Tests entries [first, first + count) of `leaves` against state->ray for the nearest hit,
/// keeping the best in *state: a triangle by its t and barycentrics (its SurfaceHit is made
/// after the walk), a sphere (or, with in_full, every primitive) with its SurfaceHit at once.
void intersect_leaf(const Scene& scene, const LeafPrimitives& leaves, uint32_t first,
                    uint32_t count, NearestHitQuery* state);

/// Whether any of entries [first, first + count) of `leaves` blocks `ray` in (tmin, tmax).
bool leaf_occludes(const Scene& scene, const LeafPrimitives& leaves, uint32_t first,
                   uint32_t count, const Ray& ray);

}  // namespace pt
