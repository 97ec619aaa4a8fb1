// Triangle meshes the generator builds: the box's walls, the helix coil, the dense test mesh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace scenegen {

/// An indexed triangle mesh with its own normal list. Positions are shared between triangles by
/// index (so a loader gives neighbouring triangles bit-identical corners); normals have indices of
/// their own because a flat wall wants one normal per face while a smooth surface wants one per
/// vertex (then normal_indices equals triangles).
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<std::array<uint32_t, 3>> triangles;       ///< indices into positions
  std::vector<std::array<uint32_t, 3>> normal_indices;  ///< indices into normals, per corner
};

/// A flat quad a-b-c-d (in order round its rim) as two triangles (a,b,c) and (a,c,d) with one
/// normal per face, wound counter-clockwise seen from the side `normal` points to (the corners
/// are reordered if they were given the other way round).
Mesh make_quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
               const glm::vec3& normal);

/// A tube of circular cross-section swept along a helix about +Z, closed at both ends by
/// hemispherical caps, so the surface is smooth (one normal per vertex) and watertight.
struct CoilParams {
  double helix_radius = 0.4;   ///< distance of the tube's centre line from the Z axis
  double pitch = 0.22;         ///< rise per turn; more than twice tube_radius so turns don't touch
  double turns = 4.0;
  double tube_radius = 0.07;
  int segments_per_turn = 48;  ///< rings along the centre line per turn
  int sides = 16;              ///< vertices round each ring
  int cap_rings = 4;           ///< latitude bands of each hemispherical cap
};
Mesh make_coil(const CoilParams& params);
/// Triangle count make_coil gives, without building it.
uint64_t coil_triangle_count(const CoilParams& params);

/// A sphere made from a cube whose faces are split into resolution × resolution squares, each
/// point pushed out to the unit sphere and then displaced radially by a smooth bumpy function.
/// Star-shaped, so it never intersects itself; shared cube edges and corners share vertices.
/// 12·resolution² triangles, 6·resolution² + 2 vertices, smooth per-vertex normals.
struct DenseParams {
  int resolution = 289;        ///< 289 gives 1,002,252 triangles
  double bump_amplitude = 0.08;
  double bump_frequency = 7.0;
};
Mesh make_dense_sphere(const DenseParams& params);
uint64_t dense_sphere_triangle_count(const DenseParams& params);

/// A closed cylinder about +Z from z = 0 to `height`: one band of `sides` quads round it and a
/// fan at each end, so every triangle is a long thin sliver (sides and cap wedges alike).
struct ColumnParams {
  double radius = 0.03;
  double height = 1.4;
  int sides = 2048;
};
Mesh make_column(const ColumnParams& params);
uint64_t column_triangle_count(const ColumnParams& params);

/// Per-vertex normals as the area-weighted sum of the faces round each vertex, normalised.
/// Sets normal_indices = triangles.
void set_smooth_normals(Mesh& mesh);

}  // namespace scenegen
