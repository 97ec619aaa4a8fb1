// What a ray learns where it hits a surface.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

namespace pt {

/// The nearest hit of a ray. p_error bounds, per axis, how far the computed p can be from the
/// exact point on the surface; rays leaving the surface start outside that box
/// (offset_ray_origin), which is what keeps them from hitting the surface they leave.
struct SurfaceHit {
  float t = 0.0f;
  glm::vec3 p{0.0f};
  glm::vec3 p_error{0.0f};
  /// Geometric normal, unit length: a sphere's outward normal; a triangle's winding normal,
  /// flipped when needed to the side of its interpolated vertex normals (the modeller's normals
  /// say which side is outside).
  glm::vec3 ng{0.0f, 0.0f, 1.0f};
  /// Shading normal, unit length, in ng's hemisphere: the interpolated vertex normals, or ng
  /// when the mesh has none.
  glm::vec3 n{0.0f, 0.0f, 1.0f};
  uint32_t primitive = 0;
  uint32_t material = 0;
};

/// A ray-triangle hit before it becomes a SurfaceHit: the distance and the barycentric
/// coordinates of the hit point (b0 weighs the first corner).
struct TriangleHit {
  float t = 0.0f;
  float b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
};

}  // namespace pt
