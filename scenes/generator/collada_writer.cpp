#include "scenes/generator/collada_writer.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <pugixml.hpp>

namespace scenegen {
namespace {

// Text of numbers, appended to one buffer per element: the dense mesh has millions of them.
class NumberText {
 public:
  NumberText& operator<<(float v) {
    sep();
    text_ += format_float(v);
    return *this;
  }
  NumberText& operator<<(uint64_t v) {
    sep();
    char buf[24];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    text_.append(buf, end);
    return *this;
  }
  NumberText& operator<<(const glm::vec3& v) { return *this << v.x << v.y << v.z; }
  const std::string& str() const { return text_; }
  void reserve(size_t n) { text_.reserve(n); }

 private:
  void sep() {
    if (!text_.empty()) text_ += ' ';
  }
  std::string text_;
};

std::string rgb(const glm::vec3& c) { return (NumberText() << c).str(); }
std::string rgba(const glm::vec3& c) { return (NumberText() << c << 1.0f).str(); }

pugi::xml_node child_text(pugi::xml_node parent, const char* name, const std::string& text) {
  pugi::xml_node n = parent.append_child(name);
  n.text().set(text.c_str());
  return n;
}

void error(const std::string& what) { throw std::invalid_argument("COLLADA writer: " + what); }

// Names must be unique within a library, or a url="#id" would be ambiguous.
template <class T>
std::set<std::string> unique_names(const std::vector<T>& items, const char* library) {
  std::set<std::string> names;
  for (const T& item : items)
    if (item.name.empty() || !names.insert(item.name).second)
      error(std::string(library) + ": empty or duplicate name '" + item.name + "'");
  return names;
}

void write_asset(pugi::xml_node root) {
  pugi::xml_node asset = root.append_child("asset");
  pugi::xml_node contributor = asset.append_child("contributor");
  child_text(contributor, "author", "pathtracer scene_gen");
  child_text(contributor, "authoring_tool", "scenes/generator");
  // Fixed dates: the output must not change from one run to the next.
  child_text(asset, "created", "2024-01-01T00:00:00");
  child_text(asset, "modified", "2024-01-01T00:00:00");
  pugi::xml_node unit = asset.append_child("unit");
  unit.append_attribute("name") = "meter";
  unit.append_attribute("meter") = "1";
  child_text(asset, "up_axis", "Z_UP");
}

void write_light(pugi::xml_node lib, const AreaLight& light) {
  pugi::xml_node l = lib.append_child("light");
  l.append_attribute("id") = (light.name + "-light").c_str();
  l.append_attribute("name") = light.name.c_str();
  // Blender's exporter writes its area lamps as points with these attenuation terms.
  pugi::xml_node point = l.append_child("technique_common").append_child("point");
  child_text(point, "color", rgb(light.radiance)).append_attribute("sid") = "color";
  child_text(point, "constant_attenuation", "1");
  child_text(point, "linear_attenuation", "0");
  child_text(point, "quadratic_attenuation", "0.001599967");
  pugi::xml_node tech = l.append_child("extra").append_child("technique");
  tech.append_attribute("profile") = "CGL";
  child_text(tech.append_child("area"), "color", rgb(light.radiance)).append_attribute("sid") = "color";
}

void write_camera(pugi::xml_node lib, const PerspectiveCamera& cam) {
  pugi::xml_node c = lib.append_child("camera");
  c.append_attribute("id") = (cam.name + "-camera").c_str();
  c.append_attribute("name") = cam.name.c_str();
  pugi::xml_node p = c.append_child("optics").append_child("technique_common").append_child("perspective");
  child_text(p, "xfov", format_float(cam.xfov_degrees)).append_attribute("sid") = "xfov";
  child_text(p, "aspect_ratio", format_float(cam.aspect_ratio));
  child_text(p, "znear", format_float(cam.znear)).append_attribute("sid") = "znear";
  child_text(p, "zfar", format_float(cam.zfar)).append_attribute("sid") = "zfar";
}

void write_effect(pugi::xml_node lib, const Material& m) {
  pugi::xml_node e = lib.append_child("effect");
  e.append_attribute("id") = (m.name + "-effect").c_str();
  pugi::xml_node tech = e.append_child("profile_COMMON").append_child("technique");
  tech.append_attribute("sid") = "common";
  pugi::xml_node phong = tech.append_child("phong");
  bool shiny = m.model != Material::Model::diffuse;
  auto color = [&](const char* name, const glm::vec3& c) {
    child_text(phong.append_child(name), "color", rgba(c)).append_attribute("sid") = name;
  };
  auto scalar = [&](const char* name, float v) {
    child_text(phong.append_child(name), "float", format_float(v)).append_attribute("sid") = name;
  };
  color("emission", glm::vec3(0.0f));
  color("ambient", glm::vec3(0.0f));
  color("diffuse", m.diffuse);
  color("specular", glm::vec3(shiny ? 0.5f : 0.0f));
  scalar("shininess", shiny ? 50.0f : 1.0f);
  scalar("index_of_refraction", 1.0f);

  bool emits = m.emission != glm::vec3(0.0f);
  if (!emits && !shiny) return;
  pugi::xml_node cgl = e.append_child("extra").append_child("technique");
  cgl.append_attribute("profile") = "CGL";
  if (emits) child_text(cgl.append_child("emission"), "radiance", rgb(m.emission));
  if (m.model == Material::Model::mirror) {
    child_text(cgl.append_child("mirror"), "reflectance", rgb(m.reflectance));
  } else if (m.model == Material::Model::glass) {
    pugi::xml_node g = cgl.append_child("glass");
    child_text(g, "reflectance", rgb(m.reflectance));
    child_text(g, "transmittance", rgb(m.transmittance));
    child_text(g, "roughness", format_float(m.roughness));
    child_text(g, "ior", format_float(m.ior));
  }
}

void write_material(pugi::xml_node lib, const Material& m) {
  pugi::xml_node mat = lib.append_child("material");
  mat.append_attribute("id") = (m.name + "-material").c_str();
  mat.append_attribute("name") = m.name.c_str();
  mat.append_child("instance_effect").append_attribute("url") = ("#" + m.name + "-effect").c_str();
}

void write_source(pugi::xml_node mesh, const std::string& id, const NumberText& values, size_t count,
                  const char* const* params, int stride) {
  pugi::xml_node src = mesh.append_child("source");
  src.append_attribute("id") = id.c_str();
  pugi::xml_node arr = child_text(src, "float_array", values.str());
  arr.append_attribute("id") = (id + "-array").c_str();
  arr.append_attribute("count") = uint64_t(count) * uint64_t(stride);
  pugi::xml_node acc = src.append_child("technique_common").append_child("accessor");
  acc.append_attribute("source") = ("#" + id + "-array").c_str();
  acc.append_attribute("count") = uint64_t(count);
  acc.append_attribute("stride") = stride;
  for (int i = 0; i < stride; ++i) {
    pugi::xml_node p = acc.append_child("param");
    p.append_attribute("name") = params[i];
    p.append_attribute("type") = "float";
  }
}

void write_mesh(pugi::xml_node lib, const MeshGeometry& g, const std::string& symbol) {
  const Mesh& m = g.mesh;
  if (m.triangles.empty()) error("mesh '" + g.name + "' has no triangles");
  if (m.normal_indices.size() != m.triangles.size())
    error("mesh '" + g.name + "': normal_indices and triangles differ in count");
  for (size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (m.triangles[t][k] >= m.positions.size() || m.normal_indices[t][k] >= m.normals.size())
        error("mesh '" + g.name + "': triangle " + std::to_string(t) + " has an index out of range");

  const std::string id = g.name + "-mesh";
  pugi::xml_node geom = lib.append_child("geometry");
  geom.append_attribute("id") = id.c_str();
  geom.append_attribute("name") = g.name.c_str();
  pugi::xml_node mesh = geom.append_child("mesh");
  static const char* const xyz[] = {"X", "Y", "Z"};
  static const char* const st[] = {"S", "T"};

  NumberText positions, normals;
  positions.reserve(m.positions.size() * 36);
  normals.reserve(m.normals.size() * 36);
  for (const glm::vec3& p : m.positions) positions << p;
  for (const glm::vec3& n : m.normals) normals << n;
  write_source(mesh, id + "-positions", positions, m.positions.size(), xyz, 3);
  write_source(mesh, id + "-normals", normals, m.normals.size(), xyz, 3);
  const size_t corners = 3 * m.triangles.size();
  if (g.texcoords) {
    NumberText uv;
    for (size_t i = 0; i < corners; ++i) uv << 0.0f << 1.0f;
    write_source(mesh, id + "-map-0", uv, corners, st, 2);
  }
  pugi::xml_node vertices = mesh.append_child("vertices");
  vertices.append_attribute("id") = (id + "-vertices").c_str();
  pugi::xml_node vin = vertices.append_child("input");
  vin.append_attribute("semantic") = "POSITION";
  vin.append_attribute("source") = ("#" + id + "-positions").c_str();

  bool poly = g.faces == MeshGeometry::Faces::polylist;
  pugi::xml_node faces = mesh.append_child(poly ? "polylist" : "triangles");
  faces.append_attribute("material") = symbol.c_str();
  faces.append_attribute("count") = uint64_t(m.triangles.size());
  auto input = [&](const char* semantic, const std::string& source, int offset) {
    pugi::xml_node in = faces.append_child("input");
    in.append_attribute("semantic") = semantic;
    in.append_attribute("source") = ("#" + source).c_str();
    in.append_attribute("offset") = offset;
    return in;
  };
  input("VERTEX", id + "-vertices", 0);
  input("NORMAL", id + "-normals", 1);
  if (g.texcoords) input("TEXCOORD", id + "-map-0", 2).append_attribute("set") = 0;
  if (poly) {
    std::string vcount;
    vcount.reserve(2 * m.triangles.size());
    for (size_t t = 0; t < m.triangles.size(); ++t) vcount += t ? " 3" : "3";
    child_text(faces, "vcount", vcount);
  }
  NumberText p;
  p.reserve(corners * (g.texcoords ? 24 : 16));
  for (size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      p << uint64_t(m.triangles[t][k]) << uint64_t(m.normal_indices[t][k]);
      if (g.texcoords) p << uint64_t(3 * t + k);
    }
  child_text(faces, "p", p.str());
}

void write_sphere(pugi::xml_node lib, const SphereGeometry& s) {
  if (!(s.radius > 0.0f)) error("sphere '" + s.name + "' needs a positive radius");
  pugi::xml_node geom = lib.append_child("geometry");
  geom.append_attribute("id") = (s.name + "-data").c_str();
  geom.append_attribute("name") = s.name.c_str();
  pugi::xml_node tech = geom.append_child("extra").append_child("technique");
  tech.append_attribute("profile") = "CGL";
  child_text(tech.append_child("sphere"), "radius", format_float(s.radius));
}

// COLLADA's <matrix> is row-major; glm stores columns.
std::string matrix_text(const glm::mat4& m) {
  NumberText t;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) t << m[col][row];
  return t.str();
}

}  // namespace

std::string format_float(float value) {
  if (!std::isfinite(value)) error("a number is not finite");
  if (value == 0.0f) return "0";
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, end);
}

std::string to_collada(const Document& doc) {
  const auto light_names = unique_names(doc.lights, "library_lights");
  const auto camera_names = unique_names(doc.cameras, "library_cameras");
  const auto material_names = unique_names(doc.materials, "library_materials");
  const auto mesh_names = unique_names(doc.meshes, "library_geometries");
  std::set<std::string> geometry_names = mesh_names;
  for (const std::string& s : unique_names(doc.spheres, "library_geometries"))
    if (!geometry_names.insert(s).second) error("library_geometries: duplicate name '" + s + "'");
  unique_names(doc.nodes, "visual_scene");

  // Each mesh's faces name a material symbol; like Blender, use the id of the material its first
  // node binds, and let every node bind that symbol to its own material.
  std::map<std::string, std::string> symbol_of;
  for (const Node& n : doc.nodes) {
    const std::set<std::string>* names = n.kind == Node::Kind::geometry ? &geometry_names
                                         : n.kind == Node::Kind::light  ? &light_names
                                                                        : &camera_names;
    if (!names->count(n.instance)) error("node '" + n.name + "' instances unknown '" + n.instance + "'");
    if (n.kind == Node::Kind::geometry) {
      if (!material_names.count(n.material))
        error("node '" + n.name + "' binds unknown material '" + n.material + "'");
      symbol_of.emplace(n.instance, n.material + "-material");
    }
  }

  pugi::xml_document xml;
  pugi::xml_node decl = xml.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "utf-8";
  pugi::xml_node root = xml.append_child("COLLADA");
  root.append_attribute("xmlns") = "http://www.collada.org/2005/11/COLLADASchema";
  root.append_attribute("version") = "1.4.1";
  write_asset(root);

  pugi::xml_node lights = root.append_child("library_lights");
  for (const AreaLight& l : doc.lights) write_light(lights, l);
  pugi::xml_node cameras = root.append_child("library_cameras");
  for (const PerspectiveCamera& c : doc.cameras) write_camera(cameras, c);
  root.append_child("library_images");
  pugi::xml_node effects = root.append_child("library_effects");
  for (const Material& m : doc.materials) write_effect(effects, m);
  pugi::xml_node materials = root.append_child("library_materials");
  for (const Material& m : doc.materials) write_material(materials, m);
  pugi::xml_node geometries = root.append_child("library_geometries");
  for (const SphereGeometry& s : doc.spheres) write_sphere(geometries, s);
  for (const MeshGeometry& g : doc.meshes) {
    auto it = symbol_of.find(g.name);
    write_mesh(geometries, g, it != symbol_of.end() ? it->second : "material");
  }
  root.append_child("library_controllers");

  pugi::xml_node scene = root.append_child("library_visual_scenes").append_child("visual_scene");
  scene.append_attribute("id") = "Scene";
  scene.append_attribute("name") = "Scene";
  for (const Node& n : doc.nodes) {
    pugi::xml_node node = scene.append_child("node");
    node.append_attribute("id") = n.name.c_str();
    node.append_attribute("name") = n.name.c_str();
    node.append_attribute("type") = "NODE";
    child_text(node, "matrix", matrix_text(n.transform)).append_attribute("sid") = "transform";
    if (n.kind == Node::Kind::light) {
      node.append_child("instance_light").append_attribute("url") = ("#" + n.instance + "-light").c_str();
    } else if (n.kind == Node::Kind::camera) {
      node.append_child("instance_camera").append_attribute("url") = ("#" + n.instance + "-camera").c_str();
    } else {
      bool is_mesh = mesh_names.count(n.instance) > 0;
      pugi::xml_node inst = node.append_child("instance_geometry");
      inst.append_attribute("url") = ("#" + n.instance + (is_mesh ? "-mesh" : "-data")).c_str();
      pugi::xml_node im =
          inst.append_child("bind_material").append_child("technique_common").append_child("instance_material");
      im.append_attribute("symbol") = symbol_of.at(n.instance).c_str();
      im.append_attribute("target") = ("#" + n.material + "-material").c_str();
    }
  }
  root.append_child("scene").append_child("instance_visual_scene").append_attribute("url") = "#Scene";

  std::ostringstream out;
  xml.save(out, "  ", pugi::format_indent, pugi::encoding_utf8);
  return out.str();
}

void write_collada(const Document& doc, const std::string& path) {
  const std::string text = to_collada(doc);
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path + ": cannot open for writing");
  file.write(text.data(), std::streamsize(text.size()));
  file.close();
  if (!file) throw std::runtime_error(path + ": write failed");
}

}  // namespace scenegen
