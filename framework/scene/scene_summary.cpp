// Not needed for the assignment: the definitions of framework/scene/scene_summary.h.
#include "framework/scene/scene_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>

namespace pt {
namespace {

constexpr MaterialKind kAllMaterialKinds[] = {MaterialKind::diffuse, MaterialKind::mirror,
                                              MaterialKind::glass, MaterialKind::microfacet,
                                              MaterialKind::emission};
constexpr LightKind kAllLightKinds[] = {LightKind::point, LightKind::spot, LightKind::directional,
                                        LightKind::ambient, LightKind::area};

std::string fmt(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", double(v));
  return buf;
}
std::string fmt(const glm::vec3& v) { return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")"; }
nlohmann::json js(const glm::vec3& v) { return {v.x, v.y, v.z}; }

/// Primitives whose material emits: the geometry a light-importance sampler would have to find.
size_t emissive_primitives(const Scene& s) {
  size_t n = 0;
  for (const Triangle& t : s.triangles) n += s.materials[t.material].emissive();
  for (const Sphere& sp : s.spheres) n += s.materials[sp.material].emissive();
  return n;
}

struct CameraFacts {
  glm::vec3 position, direction, up;
};
CameraFacts camera_facts(const Camera& c) {
  const glm::mat4& m = c.camera_to_world;
  return {glm::vec3(m[3]), glm::normalize(-glm::vec3(m[2])), glm::normalize(glm::vec3(m[1]))};
}

}  // namespace

std::string describe_scene(const Scene& s) {
  std::ostringstream o;
  o << "scene:      " << s.source << " (up axis " << s.up_axis << ")\n";
  o << "triangles:  " << s.triangles.size() << "\n";
  o << "spheres:    " << s.spheres.size() << "\n";
  o << "vertices:   " << s.positions.size() << (s.normals.empty() ? " (no shading normals)" : " (with shading normals)") << "\n";
  o << "materials:  " << s.materials.size() << "\n";
  for (MaterialKind k : kAllMaterialKinds) {
    std::vector<std::string> names;
    for (const Material& m : s.materials)
      if (m.kind == k) names.push_back(m.name + (m.emissive() ? " (emits " + fmt(m.emission) + ")" : ""));
    if (names.empty()) continue;
    o << "  " << to_string(k) << " " << names.size() << ":";
    for (size_t i = 0; i < names.size(); ++i) o << (i ? ", " : " ") << names[i];
    o << "\n";
  }
  o << "emissive primitives: " << emissive_primitives(s) << "\n";
  o << "lights:     " << s.lights.size() << "\n";
  for (const Light& l : s.lights) {
    o << "  " << to_string(l.kind) << " radiance " << fmt(l.radiance);
    if (l.kind == LightKind::point || l.kind == LightKind::spot || l.kind == LightKind::area)
      o << " at " << fmt(l.position);
    if (l.kind == LightKind::spot || l.kind == LightKind::directional || l.kind == LightKind::area)
      o << " facing " << fmt(l.direction);
    if (l.kind == LightKind::area) o << " edges " << fmt(l.edge_u) << " " << fmt(l.edge_v);
    o << "\n";
  }
  Bounds3 b = s.bounds();
  o << "bounds:     " << (b.empty() ? std::string("empty") : fmt(b.lo) + " to " + fmt(b.hi)) << "\n";
  CameraFacts c = camera_facts(s.camera);
  o << "camera:     " << (s.has_camera ? "from the file" : "default, framing the scene") << "\n";
  o << "  position  " << fmt(c.position) << "\n";
  o << "  direction " << fmt(c.direction) << "\n";
  o << "  up        " << fmt(c.up) << "\n";
  o << "  hfov      " << fmt(s.camera.hfov_degrees) << " degrees, aspect " << fmt(s.camera.aspect) << "\n";
  return o.str();
}

nlohmann::json describe_scene_json(const Scene& s) {
  nlohmann::json j;
  j["file"] = s.source;
  j["up_axis"] = s.up_axis;
  j["triangles"] = s.triangles.size();
  j["spheres"] = s.spheres.size();
  j["vertices"] = s.positions.size();
  j["has_normals"] = !s.normals.empty();
  nlohmann::json mats = nlohmann::json::array();
  nlohmann::json by_kind = nlohmann::json::object();
  for (MaterialKind k : kAllMaterialKinds) by_kind[to_string(k)] = 0;
  for (const Material& m : s.materials) {
    mats.push_back({{"name", m.name}, {"kind", to_string(m.kind)}, {"emission", js(m.emission)}});
    by_kind[to_string(m.kind)] = by_kind[to_string(m.kind)].get<int>() + 1;
  }
  j["materials"] = mats;
  j["materials_by_kind"] = by_kind;
  j["emissive_primitives"] = emissive_primitives(s);
  nlohmann::json lights = nlohmann::json::array();
  nlohmann::json lights_by_kind = nlohmann::json::object();
  for (LightKind k : kAllLightKinds) lights_by_kind[to_string(k)] = 0;
  for (const Light& l : s.lights) {
    nlohmann::json e = {{"kind", to_string(l.kind)}, {"radiance", js(l.radiance)},
                        {"position", js(l.position)}, {"direction", js(l.direction)}};
    if (l.kind == LightKind::area) e["edges"] = {js(l.edge_u), js(l.edge_v)};
    lights.push_back(e);
    lights_by_kind[to_string(l.kind)] = lights_by_kind[to_string(l.kind)].get<int>() + 1;
  }
  j["lights"] = lights;
  j["lights_by_kind"] = lights_by_kind;
  Bounds3 b = s.bounds();
  j["bounds"] = b.empty() ? nlohmann::json(nullptr) : nlohmann::json{{"lo", js(b.lo)}, {"hi", js(b.hi)}};
  CameraFacts c = camera_facts(s.camera);
  j["camera"] = {{"from_file", s.has_camera},     {"position", js(c.position)},
                 {"direction", js(c.direction)},  {"up", js(c.up)},
                 {"hfov_degrees", s.camera.hfov_degrees}, {"aspect", s.camera.aspect}};
  return j;
}

std::string materials_falling_back(const Scene& s, const std::vector<MaterialKind>& rendered) {
  std::string names;
  size_t count = 0;
  for (const Material& m : s.materials) {
    if (std::find(rendered.begin(), rendered.end(), m.kind) != rendered.end()) continue;
    names += (count++ ? ", " : "") + m.name + " (" + to_string(m.kind) + ")";
  }
  if (!count) return "";
  return std::to_string(count) +
         (count == 1 ? " material is drawn as diffuse until its kind is implemented: "
                     : " materials are drawn as diffuse until their kinds are implemented: ") +
         names;
}

}  // namespace pt
