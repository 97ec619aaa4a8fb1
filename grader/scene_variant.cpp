#include "grader/scene_variant.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>

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
