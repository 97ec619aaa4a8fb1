// What every scene the loader returns must hold, whatever the file: what the fuzz target and the
// corpus test check beyond "no crash".
#pragma once

#include <cmath>
#include <string>

#include "framework/scene/scene.h"

namespace pt::fuzz {

/// The first broken promise of a loaded scene, or "" when it keeps them all: indices in range,
/// positions finite, one unit normal per position, a finite camera, radiances not negative,
/// reflectances in [0, 1].
inline std::string scene_invariant_violation(const Scene& s) {
  auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  auto in_unit = [](const glm::vec3& v) {
    return v.x >= 0 && v.x <= 1 && v.y >= 0 && v.y <= 1 && v.z >= 0 && v.z <= 1;
  };
  if (s.primitive_count() == 0) return "a scene with nothing in it";
  if (s.normals.size() != s.positions.size()) return "normals and positions differ in number";
  for (const glm::vec3& p : s.positions)
    if (!finite(p)) return "a position is not finite";
  for (const glm::vec3& n : s.normals)
    if (!finite(n) || std::abs(glm::dot(n, n) - 1.0f) > 1e-3f) return "a normal is not of unit length";
  for (const Triangle& t : s.triangles) {
    for (uint32_t v : t.v)
      if (v >= s.positions.size()) return "a triangle's vertex index is out of range";
    if (t.material >= s.materials.size()) return "a triangle's material index is out of range";
  }
  for (const Sphere& sp : s.spheres)
    if (!(sp.radius > 0.0f) || !std::isfinite(sp.radius) || !finite(sp.center) ||
        sp.material >= s.materials.size())
      return "a sphere is malformed";
  for (const Material& m : s.materials)
    if (!in_unit(m.albedo) || !in_unit(m.reflectance) || !in_unit(m.transmittance) ||
        !(m.emission.x >= 0 && m.emission.y >= 0 && m.emission.z >= 0) || !(m.roughness >= 0))
      return "material \"" + m.name + "\" holds an impossible value";
  for (const Light& l : s.lights)
    if (!finite(l.position) || !finite(l.direction) ||
        !(l.radiance.x >= 0 && l.radiance.y >= 0 && l.radiance.z >= 0) ||
        !(l.radiance.x > 0 || l.radiance.y > 0 || l.radiance.z > 0))
      return "a light is malformed or emits nothing";
  const glm::mat4& c = s.camera.camera_to_world;
  for (int i = 0; i < 4; ++i)
    if (!finite(glm::vec3(c[i]))) return "the camera is not finite";
  if (!(s.camera.hfov_degrees > 0.0f && s.camera.hfov_degrees < 180.0f) || !(s.camera.aspect > 0.0f))
    return "the camera's field of view is impossible";
  return "";
}

}  // namespace pt::fuzz
