// Writes a scene description as COLLADA 1.4 in the course's dialect (Blender layout + CGL extras).
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scenes/generator/mesh.h"

namespace scenegen {

/// A Blender-style lamp: written as a <point> light (what plain COLLADA readers see) plus the
/// CGL <area> extension whose unit square the node's matrix scales and places.
struct AreaLight {
  std::string name;  ///< the light's id is name + "-light"
  glm::vec3 radiance{10.0f};
};

/// A perspective camera looking down its local −Z, as COLLADA has it.
struct PerspectiveCamera {
  std::string name;  ///< id name + "-camera"
  float xfov_degrees = 49.13434f;
  float aspect_ratio = 1.333333f;
  float znear = 0.1f;
  float zfar = 100.0f;
};

/// One effect + material pair. The phong diffuse colour is always written; the CGL extra says
/// what the surface really is (emitter, mirror, glass) when it is not plain diffuse.
struct Material {
  enum class Model { diffuse, mirror, glass };
  std::string name;  ///< material id name + "-material", effect id name + "-effect"
  Model model = Model::diffuse;
  glm::vec3 diffuse{0.8f};
  glm::vec3 emission{0.0f};       ///< CGL emission radiance; written only when non-zero
  glm::vec3 reflectance{1.0f};    ///< mirror and glass
  glm::vec3 transmittance{1.0f};  ///< glass
  float ior = 1.5f;               ///< glass
  float roughness = 0.0f;         ///< glass
};

/// A triangle mesh geometry. Both COLLADA face lists are written so readers get exercised on
/// each: <polylist> (with <vcount>, as Blender writes) or <triangles>.
struct MeshGeometry {
  enum class Faces { polylist, triangles };
  std::string name;  ///< id name + "-mesh"
  Mesh mesh;
  Faces faces = Faces::polylist;
  bool texcoords = false;  ///< add Blender's dummy UV source (every corner (0,1)), as the walls have
};

/// The CGL analytic sphere, centred on its node's origin.
struct SphereGeometry {
  std::string name;  ///< id name + "-data"
  float radius = 1.0f;
};

/// A node of the visual scene: a transform and one instance (geometry with its material, light or
/// camera), referred to by the name given to that library entry.
struct Node {
  enum class Kind { geometry, light, camera };
  std::string name;
  glm::mat4 transform{1.0f};
  Kind kind = Kind::geometry;
  std::string instance;  ///< name of the mesh, sphere, light or camera
  std::string material;  ///< geometry nodes: name of the material bound to it
};

/// A whole file's worth: the libraries and the one visual scene that instances them.
struct Document {
  std::vector<AreaLight> lights;
  std::vector<PerspectiveCamera> cameras;
  std::vector<Material> materials;
  std::vector<MeshGeometry> meshes;
  std::vector<SphereGeometry> spheres;
  std::vector<Node> nodes;
};

/// The document as COLLADA text. Deterministic: the same document gives the same bytes. Floats are
/// written in the shortest form that reads back as the very same float, so a vertex shared by
/// index stays bit-identical after loading. Throws std::invalid_argument for a node naming
/// something the document lacks, a duplicate name, an index out of range or a non-finite number.
std::string to_collada(const Document& doc);

/// Writes to_collada(doc) to `path`; throws std::runtime_error naming the file if that fails.
void write_collada(const Document& doc, const std::string& path);

/// Shortest round-trip text of a float ("0.3", "1e-07"); −0 is written as "0".
std::string format_float(float value);

}  // namespace scenegen
