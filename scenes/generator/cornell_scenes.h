// The project's own scenes: Cornell boxes laid out like the course's, with spheres or meshes in them.
#pragma once

#include <string>
#include <vector>

#include "scenes/generator/collada_writer.h"
#include "scenes/generator/mesh.h"

namespace scenegen {

/// One scene the generator can write, by the stem of its file name.
struct SceneEntry {
  std::string name;     ///< "cornell_coil" is written as cornell_coil.dae
  std::string summary;  ///< one line for --list and the README
  bool committed;       ///< small enough to keep in the repository (the rest are written on demand)
};

/// Every scene the generator knows, committed ones first, in a fixed order.
std::vector<SceneEntry> scene_entries();

/// Knobs of the procedural meshes, so tests can build smaller ones than the files hold.
struct SceneOptions {
  CoilParams coil;
  DenseParams dense;  ///< dense_sphere's sphere
  /// dense_mesh's statue: most of its million triangles (12 · 268² = 861,888).
  DenseParams statue{268, 0.08, 7.0};
  /// dense_mesh's coil: thinner, tighter and more finely tessellated than cornell_coil's.
  CoilParams room_coil{0.12, 0.06, 6.0, 0.02, 96, 24, 4};
  ColumnParams column;  ///< dense_mesh's two columns
};

/// The course's Cornell box: a 2 × 2 × 1.5 box (red left wall, blue right wall, white floor,
/// ceiling and back), an emitting panel just under the ceiling with a CGL area light of the
/// same size and radiance, and the camera 3 units in front looking in.
Document cornell_box();

/// The named scene (see scene_entries()); throws std::invalid_argument for a name it lacks.
Document build_scene(const std::string& name, const SceneOptions& options = {});

}  // namespace scenegen
