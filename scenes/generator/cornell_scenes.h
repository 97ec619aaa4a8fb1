// The project's own scenes: Cornell boxes laid out like the course's, with spheres or meshes in them.
#pragma once

#include <string>
#include <vector>

#include "generator/collada_writer.h"
#include "generator/mesh.h"

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
  DenseParams dense;
};

/// The course's Cornell box: a 2 × 2 × 1.5 box (red left wall, blue right wall, white floor,
/// ceiling and back), an emitting panel just under the ceiling with a CGL area light of the
/// same size and radiance, and the camera 3 units in front looking in.
Document cornell_box();

/// The named scene (see scene_entries()); throws std::invalid_argument for a name it lacks.
Document build_scene(const std::string& name, const SceneOptions& options = {});

}  // namespace scenegen
