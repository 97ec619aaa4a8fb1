#include "grader/scene_variant.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <pugixml.hpp>

#include "framework/sampling/rng.h"

namespace pt::grader {
namespace {

bool is_transform(const char* name) {
  std::string n = name;
  return n == "matrix" || n == "translate" || n == "rotate" || n == "scale" || n == "lookat";
}

std::string numbers(std::initializer_list<double> v) {
  std::ostringstream s;
  s.precision(9);
  bool first = true;
  for (double x : v) {
    s << (first ? "" : " ") << x;
    first = false;
  }
  return s.str();
}

/// The camera's position from its node's first matrix (or translate): how far to move it.
double camera_distance(pugi::xml_node node) {
  for (pugi::xml_node t : node.children()) {
    std::string n = t.name();
    std::istringstream in(t.child_value());
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    if (n == "matrix" && v.size() == 16) return std::sqrt(v[3] * v[3] + v[7] * v[7] + v[11] * v[11]);
    if (n == "translate" && v.size() == 3) return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n == "lookat" && v.size() == 9) return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  return 1.0;
}

/// The numbers of an element's text.
std::vector<double> numbers_of(pugi::xml_node node) {
  std::istringstream in(node.child_value());
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

/// The element of `doc` whose id is `url` without its '#', or an empty node.
pugi::xml_node by_url(const pugi::xml_document& doc, const std::string& url) {
  if (url.size() < 2 || url[0] != '#') return {};
  return doc.find_node([&](pugi::xml_node n) { return url.compare(1, std::string::npos, n.attribute("id").value()) == 0; });
}

/// An axis-aligned box in world space.
struct Box {
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void grow(const double p[3]) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  void grow(const Box& b) {
    grow(b.lo);
    grow(b.hi);
  }
  bool valid() const { return lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]; }
};

/// A top-level node's transform, row-major, when it is one <matrix> or <translate>s only.
bool node_matrix(pugi::xml_node node, double m[16]) {
  for (int i = 0; i < 16; ++i) m[i] = (i % 5 == 0) ? 1.0 : 0.0;
  int matrices = 0;
  for (pugi::xml_node t : node.children()) {
    if (!is_transform(t.name())) continue;
    const std::vector<double> v = numbers_of(t);
    const std::string n = t.name();
    if (n == "matrix" && v.size() == 16 && matrices++ == 0) {
      for (int i = 0; i < 16; ++i) m[i] = v[size_t(i)];
    } else if (n == "translate" && v.size() == 3) {
      m[3] += v[0], m[7] += v[1], m[11] += v[2];
    } else {
      return false;
    }
  }
  return true;
}

/// The world-space box of a node's geometry (a mesh's positions or a sphere of the course's
/// <extra>), or an invalid box.
Box geometry_box(const pugi::xml_document& doc, pugi::xml_node node) {
  Box box;
  double m[16];
  pugi::xml_node instance = node.child("instance_geometry");
  if (!instance || !node_matrix(node, m)) return box;
  pugi::xml_node geometry = by_url(doc, instance.attribute("url").value());
  auto world = [&](double x, double y, double z, double out[3]) {
    for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
  };
  if (pugi::xml_node radius = geometry.select_node(".//sphere/radius").node()) {
    const double rad = std::atof(radius.child_value());
    for (int corner = 0; corner < 8; ++corner) {
      double p[3];
      world(corner & 1 ? rad : -rad, corner & 2 ? rad : -rad, corner & 4 ? rad : -rad, p);
      box.grow(p);
    }
    return box;
  }
  pugi::xml_node input = geometry.select_node("mesh/vertices/input[@semantic='POSITION']").node();
  pugi::xml_node source = by_url(doc, input.attribute("source").value());
  const std::vector<double> v = numbers_of(source.child("float_array"));
  for (size_t i = 0; i + 2 < v.size(); i += 3) {
    double p[3];
    world(v[i], v[i + 1], v[i + 2], p);
    box.grow(p);
  }
  return box;
}

/// Whether a node's bound material emits light (any nonzero number under its effect's
/// <emission>): a light's panel stays where its light is.
bool emits(const pugi::xml_document& doc, pugi::xml_node node) {
  for (pugi::xpath_node im : node.select_nodes(".//instance_material")) {
    pugi::xml_node material = by_url(doc, im.node().attribute("target").value());
    pugi::xml_node effect = by_url(doc, material.child("instance_effect").attribute("url").value());
    for (pugi::xpath_node e : effect.select_nodes(".//emission"))
      for (pugi::xml_node c : e.node().children()) {
        const std::vector<double> v = numbers_of(c);
        for (size_t i = 0; i < std::min<size_t>(3, v.size()); ++i)
          if (v[i] != 0.0) return true;
      }
  }
  return false;
}

}  // namespace

SceneVariant write_scene_variant(const std::string& scene, uint64_t key, const std::string& out) {
  pugi::xml_document doc;
  pugi::xml_parse_result parsed = doc.load_file(scene.c_str());
  if (!parsed) throw std::runtime_error(scene + ": " + parsed.description());
  Rng rng(key, 0x5eed5eedULL);
  auto uniform = [&](double a, double b) { return a + (b - a) * double(rng.next_float()); };
  SceneVariant v;
  std::ostringstream what;
  what.precision(3);

  // The camera: every node that instances one gets a small move in world space (a translate
  // before its transforms) and a small turn about its own position (a rotate after them).
  int cameras = 0;
  for (pugi::xpath_node xn : doc.select_nodes("//node[instance_camera]")) {
    pugi::xml_node node = xn.node();
    const double d = 0.03 * std::max(camera_distance(node), 0.1);
    double x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1);
    const double len = std::max(std::sqrt(x * x + y * y + z * z), 1e-3);
    x *= d / len;
    y *= d / len;
    z *= d / len;
    pugi::xml_node first = node.first_child();
    pugi::xml_node move = first ? node.insert_child_before("translate", first) : node.append_child("translate");
    move.text().set(numbers({x, y, z}).c_str());
    pugi::xml_node last_transform;
    for (pugi::xml_node t : node.children())
      if (is_transform(t.name())) last_transform = t;
    pugi::xml_node turn = node.insert_child_after("rotate", last_transform);
    const double ax = uniform(-1, 1), ay = uniform(-1, 1), az = uniform(0.2, 1), deg = uniform(1.0, 2.0);
    turn.text().set(numbers({ax, ay, az, deg}).c_str());
    what << "camera moved (" << x << ", " << y << ", " << z << ") and turned " << deg << " deg; ";
    ++cameras;
  }
  if (cameras == 0) throw std::runtime_error(scene + ": no <node> with an <instance_camera>");

  // The objects: a top-level node whose geometry lies inside the scene's box with room on both
  // sides along an axis moves along that axis by up to 2% of the scene's size (at most half the
  // room), so an object resting on the floor slides over it and none leaves the room or meets a
  // wall. Emitters, and anything the box cannot be read for, stay.
  std::vector<std::pair<pugi::xml_node, Box>> objects;
  Box scene_box;
  for (pugi::xpath_node xn : doc.select_nodes("//visual_scene/node[instance_geometry]")) {
    const Box b = geometry_box(doc, xn.node());
    if (!b.valid()) continue;
    scene_box.grow(b);
    if (!emits(doc, xn.node())) objects.push_back({xn.node(), b});
  }
  int moved = 0;
  if (scene_box.valid()) {
    double size = 0.0;
    for (int a = 0; a < 3; ++a) size = std::max(size, scene_box.hi[a] - scene_box.lo[a]);
    for (auto& [node, b] : objects) {
      double shift[3] = {0.0, 0.0, 0.0};
      bool any = false;
      for (int a = 0; a < 3; ++a) {
        const double room = std::min(b.lo[a] - scene_box.lo[a], scene_box.hi[a] - b.hi[a]);
        if (!(room > 0.01 * size)) continue;
        shift[a] = uniform(-1, 1) * std::min(0.5 * room, 0.02 * size);
        any = true;
      }
      if (!any) continue;
      pugi::xml_node first = node.first_child();
      pugi::xml_node move = node.insert_child_before("translate", first);
      move.text().set(numbers({shift[0], shift[1], shift[2]}).c_str());
      what << node.attribute("id").value() << " moved (" << shift[0] << ", " << shift[1] << ", "
           << shift[2] << "); ";
      ++moved;
    }
  }

  // The lights: every colour in <library_lights>, each channel scaled.
  const double f[3] = {uniform(0.75, 1.25), uniform(0.75, 1.25), uniform(0.75, 1.25)};
  int colours = 0;
  for (pugi::xpath_node xn : doc.select_nodes("//library_lights//color")) {
    std::istringstream in(xn.node().child_value());
    std::vector<double> c;
    for (double x; in >> x;) c.push_back(x);
    if (c.size() < 3) continue;
    xn.node().text().set(numbers({c[0] * f[0], c[1] * f[1], c[2] * f[2]}).c_str());
    ++colours;
  }
  what << colours << " light colours scaled by (" << f[0] << ", " << f[1] << ", " << f[2] << ")";
  if (!doc.save_file(out.c_str(), "  ")) throw std::runtime_error(out + ": cannot be written");
  v.description = what.str();
  return v;
}

uint64_t draw_variant_key() {
  std::random_device device;
  return (uint64_t(device()) << 32) ^ uint64_t(device());
}

uint64_t variant_key_for(uint64_t key, const std::string& render) {
  uint64_t h = key ^ 0x9e3779b97f4a7c15ULL;
  for (unsigned char c : render) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

}  // namespace pt::grader
