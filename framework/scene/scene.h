// The scene model every stage reads: world-space triangles and spheres, materials, lights, camera.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "framework/math/bounds.h"
#include "framework/scene/camera.h"
#include "framework/scene/light.h"
#include "framework/scene/material.h"

namespace pt {

/// A triangle: three indices into Scene::positions (and Scene::normals, when present).
/// Triangles that share an edge share the vertex indices, hence bit-identical corners, which is
/// what a watertight intersection test needs to leave no crack between them.
struct Triangle {
  uint32_t v[3];
  uint32_t material;
};

/// An analytic sphere (the CGL <sphere> extension).
struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  uint32_t material = 0;
};

/// Everything a render needs, flattened into world space at load time (every node transform
/// applied; the file's up axis is kept, so coordinates are the file's own).
///
/// Primitives are numbered triangles first, then spheres: primitive i < triangles.size() is
/// triangles[i], otherwise spheres[i - triangles.size()].
struct Scene {
  std::string source;                 ///< file it came from (for messages)
  std::vector<glm::vec3> positions;   ///< triangle corners
  std::vector<glm::vec3> normals;     ///< per-vertex shading normals, same size as positions, or empty
  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  std::vector<Material> materials;
  std::vector<Light> lights;
  Camera camera;
  bool has_camera = false;            ///< false: the loader placed a default camera framing the bounds
  std::string up_axis = "Y_UP";       ///< the file's <up_axis> (X_UP, Y_UP or Z_UP), kept as is

  uint32_t primitive_count() const { return uint32_t(triangles.size() + spheres.size()); }
  bool is_triangle(uint32_t primitive) const { return primitive < triangles.size(); }
  Bounds3 primitive_bounds(uint32_t primitive) const;
  Bounds3 bounds() const;
};

}  // namespace pt
