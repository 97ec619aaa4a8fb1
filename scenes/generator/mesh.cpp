#include "scenes/generator/mesh.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace scenegen {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Geometry is computed in double and rounded once to float, so the committed files do not hang on
// the last bit of a float sin/cos (which differs between maths libraries far more often).
glm::vec3 to_float(const glm::dvec3& v) { return glm::vec3(v); }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

// Vertices of a ring-by-ring sweep, ordered so that consecutive rings follow the sweep direction.
class RingSweep {
 public:
  explicit RingSweep(Mesh& mesh, int sides) : mesh_(mesh), sides_(uint32_t(sides)) {}

  // Begins a ring; returns the index of its first vertex.
  uint32_t add_vertex(const glm::dvec3& p, const glm::dvec3& n) {
    mesh_.positions.push_back(to_float(p));
    mesh_.normals.push_back(to_float(glm::normalize(n)));
    return uint32_t(mesh_.positions.size() - 1);
  }

  // Two rings of `sides` vertices each, b further along the sweep: a band of quads whose
  // triangles face outward (the side the ring normals point to).
  void band(uint32_t a, uint32_t b) {
    for (uint32_t j = 0; j < sides_; ++j) {
      uint32_t j1 = (j + 1) % sides_;
      tri(a + j, b + j1, b + j);
      tri(a + j, a + j1, b + j1);
    }
  }
  // A pole before ring r (start of the sweep) or after it (end).
  void fan_before(uint32_t pole, uint32_t r) {
    for (uint32_t j = 0; j < sides_; ++j) tri(pole, r + (j + 1) % sides_, r + j);
  }
  void fan_after(uint32_t r, uint32_t pole) {
    for (uint32_t j = 0; j < sides_; ++j) tri(r + j, r + (j + 1) % sides_, pole);
  }

 private:
  void tri(uint32_t a, uint32_t b, uint32_t c) {
    mesh_.triangles.push_back({a, b, c});
    mesh_.normal_indices.push_back({a, b, c});
  }
  Mesh& mesh_;
  uint32_t sides_;
};

// The helix's centre line and its Frenet frame: for a helix the principal normal points straight
// at the axis and never flips, so the tube has no twist to correct.
struct HelixFrame {
  glm::dvec3 center, tangent, normal, binormal;
};
HelixFrame helix_frame(const CoilParams& p, double t) {
  double rise = p.pitch / (2.0 * kPi);
  HelixFrame f;
  f.center = {p.helix_radius * std::cos(t), p.helix_radius * std::sin(t), rise * t};
  f.tangent = glm::normalize(glm::dvec3(-p.helix_radius * std::sin(t), p.helix_radius * std::cos(t), rise));
  f.normal = {-std::cos(t), -std::sin(t), 0.0};
  f.binormal = glm::cross(f.tangent, f.normal);
  return f;
}

int coil_segments(const CoilParams& p) { return int(std::lround(p.turns * p.segments_per_turn)); }

void check(const CoilParams& p) {
  require(p.sides >= 3, "coil: sides must be at least 3");
  require(p.cap_rings >= 1, "coil: cap_rings must be at least 1");
  require(p.segments_per_turn >= 3 && p.turns > 0 && coil_segments(p) >= 1,
          "coil: needs at least one segment along the helix");
  require(p.tube_radius > 0 && p.helix_radius > p.tube_radius,
          "coil: tube_radius must be positive and less than helix_radius");
  require(p.pitch > 2.0 * p.tube_radius, "coil: pitch must exceed the tube's diameter");
}

}  // namespace

Mesh make_quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
               const glm::vec3& normal) {
  Mesh m;
  bool forward = glm::dot(glm::cross(b - a, c - a), normal) > 0.0f;
  m.positions = forward ? std::vector<glm::vec3>{a, b, c, d} : std::vector<glm::vec3>{a, d, c, b};
  glm::vec3 n = glm::normalize(normal);
  m.normals = {n, n};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.normal_indices = {{0, 0, 0}, {1, 1, 1}};
  return m;
}

uint64_t coil_triangle_count(const CoilParams& p) {
  check(p);
  uint64_t bands = uint64_t(coil_segments(p)) + 2u * uint64_t(p.cap_rings - 1);
  return 2u * uint64_t(p.sides) * bands + 2u * uint64_t(p.sides);
}

Mesh make_coil(const CoilParams& p) {
  check(p);
  Mesh mesh;
  RingSweep sweep(mesh, p.sides);
  const int segments = coil_segments(p);
  const double t_end = 2.0 * kPi * p.turns;

  // One ring round an end of the tube, pushed out along `axis` by a cap latitude phi.
  auto ring = [&](const HelixFrame& f, const glm::dvec3& axis, double phi) {
    uint32_t first = 0;
    for (int j = 0; j < p.sides; ++j) {
      double theta = 2.0 * kPi * j / p.sides;
      glm::dvec3 radial = std::cos(theta) * f.normal + std::sin(theta) * f.binormal;
      glm::dvec3 n = std::cos(phi) * radial + std::sin(phi) * axis;
      uint32_t v = sweep.add_vertex(f.center + p.tube_radius * n, n);
      if (j == 0) first = v;
    }
    return first;
  };

  // Sweep order: start pole, start cap rings inwards, tube rings, end cap rings outwards, end pole.
  const HelixFrame start = helix_frame(p, 0.0), end = helix_frame(p, t_end);
  const glm::dvec3 back = -start.tangent;
  uint32_t start_pole = sweep.add_vertex(start.center + p.tube_radius * back, back);
  std::vector<uint32_t> rings;
  for (int k = p.cap_rings - 1; k >= 1; --k) rings.push_back(ring(start, back, 0.5 * kPi * k / p.cap_rings));
  for (int i = 0; i <= segments; ++i) {
    double t = t_end * i / segments;
    rings.push_back(ring(helix_frame(p, t), glm::dvec3(0.0), 0.0));
  }
  for (int k = 1; k <= p.cap_rings - 1; ++k)
    rings.push_back(ring(end, end.tangent, 0.5 * kPi * k / p.cap_rings));
  uint32_t end_pole = sweep.add_vertex(end.center + p.tube_radius * end.tangent, end.tangent);

  sweep.fan_before(start_pole, rings.front());
  for (size_t i = 0; i + 1 < rings.size(); ++i) sweep.band(rings[i], rings[i + 1]);
  sweep.fan_after(rings.back(), end_pole);
  return mesh;
}

uint64_t dense_sphere_triangle_count(const DenseParams& p) {
  require(p.resolution >= 1, "dense mesh: resolution must be at least 1");
  return 12u * uint64_t(p.resolution) * uint64_t(p.resolution);
}

Mesh make_dense_sphere(const DenseParams& p) {
  const uint64_t triangle_count = dense_sphere_triangle_count(p);
  const uint32_t n = uint32_t(p.resolution);
  Mesh mesh;
  mesh.triangles.reserve(triangle_count);
  mesh.positions.reserve(6u * n * n + 2u);

  // Vertices live on the integer lattice of the cube's surface; a point on a shared edge or
  // corner is looked up by its lattice coordinates, so every face finds the same index.
  std::unordered_map<uint64_t, uint32_t> index_of;
  index_of.reserve(6u * n * n + 2u);
  auto vertex = [&](const glm::uvec3& q) {
    uint64_t key = (uint64_t(q.x) * (n + 1) + q.y) * (n + 1) + q.z;
    auto [it, inserted] = index_of.try_emplace(key, uint32_t(mesh.positions.size()));
    if (inserted) {
      // tan warp: equal steps of angle rather than of cube length, for near-uniform triangles.
      glm::dvec3 c = glm::dvec3(q) * (2.0 / n) - 1.0;
      glm::dvec3 dir = glm::normalize(glm::tan(c * (kPi / 4.0)));
      double f = p.bump_frequency;
      double r = 1.0 + p.bump_amplitude * std::sin(f * dir.x) * std::sin(f * dir.y) * std::sin(f * dir.z);
      mesh.positions.push_back(to_float(r * dir));
    }
    return it->second;
  };

  // Each face: a fixed lattice coordinate and two axes u, v with u × v pointing out of the cube.
  struct Face {
    int fixed_axis;
    uint32_t fixed_value;
    int u_axis, v_axis;
  };
  const Face faces[6] = {{0, n, 1, 2}, {0, 0, 2, 1}, {1, n, 2, 0},
                         {1, 0, 0, 2}, {2, n, 0, 1}, {2, 0, 1, 0}};
  for (const Face& face : faces) {
    auto lattice = [&](uint32_t u, uint32_t v) {
      glm::uvec3 q(0);
      q[face.fixed_axis] = face.fixed_value;
      q[face.u_axis] = u;
      q[face.v_axis] = v;
      return vertex(q);
    };
    for (uint32_t v = 0; v < n; ++v)
      for (uint32_t u = 0; u < n; ++u) {
        uint32_t a = lattice(u, v), b = lattice(u + 1, v), c = lattice(u + 1, v + 1), d = lattice(u, v + 1);
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      }
  }
  set_smooth_normals(mesh);
  return mesh;
}

uint64_t column_triangle_count(const ColumnParams& p) {
  require(p.sides >= 3, "column: sides must be at least 3");
  return 4u * uint64_t(p.sides);
}

Mesh make_column(const ColumnParams& p) {
  require(p.sides >= 3, "column: sides must be at least 3");
  require(p.radius > 0 && p.height > 0, "column: radius and height must be positive");
  Mesh mesh;
  RingSweep sweep(mesh, p.sides);
  const glm::dvec3 up(0.0, 0.0, 1.0);
  auto ring = [&](double z) {
    uint32_t first = 0;
    for (int j = 0; j < p.sides; ++j) {
      const double theta = 2.0 * kPi * j / p.sides;
      const glm::dvec3 radial(std::cos(theta), std::sin(theta), 0.0);
      const uint32_t v = sweep.add_vertex(p.radius * radial + z * up, radial);
      if (j == 0) first = v;
    }
    return first;
  };
  // Swept upwards: bottom pole, two rings, top pole.
  const uint32_t bottom = sweep.add_vertex(glm::dvec3(0.0), -up);
  const uint32_t low = ring(0.0), high = ring(p.height);
  const uint32_t top = sweep.add_vertex(p.height * up, up);
  sweep.fan_before(bottom, low);
  sweep.band(low, high);
  sweep.fan_after(high, top);
  set_smooth_normals(mesh);
  return mesh;
}

void set_smooth_normals(Mesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& t : mesh.triangles) {
    glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
    glm::dvec3 area_normal = glm::cross(b - a, c - a);  // twice the area, along the normal
    for (uint32_t v : t) sum[v] += area_normal;
  }
  mesh.normals.resize(sum.size());
  for (size_t i = 0; i < sum.size(); ++i) {
    double len = glm::length(sum[i]);
    require(len > 0.0, "mesh: vertex " + std::to_string(i) + " has no area round it");
    mesh.normals[i] = to_float(sum[i] / len);
  }
  mesh.normal_indices = mesh.triangles;
}

}  // namespace scenegen
