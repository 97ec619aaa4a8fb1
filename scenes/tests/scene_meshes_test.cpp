// The procedural meshes are closed, consistently oriented 2-manifolds with the counts they promise.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scenes/generator/cornell_scenes.h"
#include "scenes/generator/mesh.h"

namespace {

using scenegen::Mesh;

struct Topology {
  uint64_t edges = 0;             // undirected
  uint64_t bad_edge_uses = 0;     // undirected edges not used by exactly two triangles
  uint64_t misoriented = 0;       // directed edges used twice (neighbours wound opposite ways)
  uint64_t degenerate = 0;        // triangles repeating an index
  uint64_t unused_vertices = 0;
};

// Sorting the directed edges finds, without a hash map, each undirected edge's uses: a closed
// oriented 2-manifold has every edge (a,b) exactly once and its twin (b,a) exactly once.
Topology topology(const Mesh& m) {
  Topology t;
  std::vector<uint64_t> directed;
  directed.reserve(3 * m.triangles.size());
  std::vector<bool> used(m.positions.size(), false);
  for (const auto& tri : m.triangles) {
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) ++t.degenerate;
    for (int k = 0; k < 3; ++k) {
      uint64_t a = tri[k], b = tri[(k + 1) % 3];
      directed.push_back(a << 32 | b);
      used[a] = true;
    }
  }
  t.unused_vertices = uint64_t(std::count(used.begin(), used.end(), false));
  std::sort(directed.begin(), directed.end());
  for (size_t i = 0; i < directed.size();) {
    size_t j = i;
    while (j < directed.size() && directed[j] == directed[i]) ++j;
    if (j - i > 1) t.misoriented += j - i - 1;
    i = j;
  }
  std::vector<uint64_t> undirected(directed.size());
  std::transform(directed.begin(), directed.end(), undirected.begin(), [](uint64_t e) {
    uint64_t a = e >> 32, b = e & 0xffffffffu;
    return std::min(a, b) << 32 | std::max(a, b);
  });
  std::sort(undirected.begin(), undirected.end());
  for (size_t i = 0; i < undirected.size();) {
    size_t j = i;
    while (j < undirected.size() && undirected[j] == undirected[i]) ++j;
    ++t.edges;
    if (j - i != 2) ++t.bad_edge_uses;
    i = j;
  }
  return t;
}

void expect_closed_manifold(const Mesh& m, const std::string& what) {
  Topology t = topology(m);
  EXPECT_EQ(t.degenerate, 0u) << what;
  EXPECT_EQ(t.bad_edge_uses, 0u) << what << ": edges not shared by exactly two triangles";
  EXPECT_EQ(t.misoriented, 0u) << what << ": neighbouring triangles wound opposite ways";
  EXPECT_EQ(t.unused_vertices, 0u) << what;
  // A closed surface of genus 0 (a sphere or a capped tube): V − E + F = 2.
  EXPECT_EQ(int64_t(m.positions.size()) - int64_t(t.edges) + int64_t(m.triangles.size()), 2) << what;
  // A closed mesh of 3F/2 edges.
  EXPECT_EQ(2 * t.edges, 3 * m.triangles.size()) << what;
}

// Signed volume (divergence theorem); positive when the triangles face outward.
double signed_volume(const Mesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) {
    glm::dvec3 a(m.positions[t[0]]), b(m.positions[t[1]]), c(m.positions[t[2]]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

// Shading normals on the same side as the winding, unit length, one per corner.
void expect_normals_agree_with_winding(const Mesh& m, const std::string& what) {
  ASSERT_EQ(m.normal_indices.size(), m.triangles.size()) << what;
  uint64_t against = 0, not_unit = 0;
  for (size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    glm::vec3 face = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    for (int k = 0; k < 3; ++k) {
      glm::vec3 n = m.normals[m.normal_indices[i][k]];
      if (glm::dot(face, n) <= 0.0f) ++against;
      if (std::abs(glm::length(n) - 1.0f) > 1e-5f) ++not_unit;
    }
  }
  EXPECT_EQ(against, 0u) << what << ": corners whose normal faces away from the triangle";
  EXPECT_EQ(not_unit, 0u) << what;
}

TEST(SceneMeshes, CoilIsClosedWatertightAndOutward) {
  scenegen::CoilParams p;
  Mesh m = scenegen::make_coil(p);
  EXPECT_EQ(m.triangles.size(), scenegen::coil_triangle_count(p));
  EXPECT_EQ(m.triangles.size(), 6368u);
  EXPECT_GE(m.triangles.size(), 2000u);
  EXPECT_LE(m.triangles.size(), 50000u);
  EXPECT_EQ(m.normals.size(), m.positions.size()) << "one normal per vertex";
  EXPECT_EQ(m.normal_indices, m.triangles);
  expect_closed_manifold(m, "coil");
  expect_normals_agree_with_winding(m, "coil");

  // Volume of a tube of length L with two hemispherical caps: π r² L + 4/3 π r³; the polygonal
  // cross-section is a little smaller than the circle (16 sides: about 2.6% less).
  const double pi = 3.14159265358979323846;
  double length = p.turns * std::sqrt(std::pow(2 * pi * p.helix_radius, 2) + p.pitch * p.pitch);
  double r = p.tube_radius;
  double expected = pi * r * r * length + 4.0 / 3.0 * pi * r * r * r;
  double polygon = 0.5 * p.sides * std::sin(2 * pi / p.sides) / pi;  // polygon/circle area ratio
  EXPECT_NEAR(signed_volume(m) / (expected * polygon), 1.0, 0.01);
}

TEST(SceneMeshes, CoilCountsFollowItsParameters) {
  for (int sides : {3, 7, 24})
    for (int cap_rings : {1, 2, 5}) {
      scenegen::CoilParams p;
      p.sides = sides;
      p.cap_rings = cap_rings;
      p.turns = 1.5;
      p.segments_per_turn = 10;
      Mesh m = scenegen::make_coil(p);
      std::string what = "coil sides=" + std::to_string(sides) + " cap_rings=" + std::to_string(cap_rings);
      EXPECT_EQ(m.triangles.size(), scenegen::coil_triangle_count(p)) << what;
      expect_closed_manifold(m, what);
      EXPECT_GT(signed_volume(m), 0.0) << what;
    }
}

TEST(SceneMeshes, CoilRejectsTurnsThatWouldTouch) {
  scenegen::CoilParams p;
  p.pitch = 1.5 * p.tube_radius;
  EXPECT_THROW(scenegen::make_coil(p), std::invalid_argument);
}

TEST(SceneMeshes, DenseSphereIsClosedAtSmallResolutions) {
  for (int n : {1, 2, 5, 16}) {
    scenegen::DenseParams p;
    p.resolution = n;
    Mesh m = scenegen::make_dense_sphere(p);
    std::string what = "dense resolution " + std::to_string(n);
    EXPECT_EQ(m.triangles.size(), 12u * n * n) << what;
    EXPECT_EQ(m.triangles.size(), scenegen::dense_sphere_triangle_count(p)) << what;
    EXPECT_EQ(m.positions.size(), 6u * n * n + 2u) << what << ": cube edges must share vertices";
    expect_closed_manifold(m, what);
    EXPECT_GT(signed_volume(m), 0.0) << what;
    for (const glm::vec3& v : m.positions) {
      float r = glm::length(v);
      ASSERT_GE(r, 1.0f - p.bump_amplitude - 1e-5f) << what;
      ASSERT_LE(r, 1.0f + p.bump_amplitude + 1e-5f) << what;
    }
  }
}

TEST(SceneMeshes, DenseSphereAtFullSizeHasAMillionTriangles) {
  auto start = std::chrono::steady_clock::now();
  scenegen::DenseParams p;  // the resolution dense_mesh.dae is written with
  Mesh m = scenegen::make_dense_sphere(p);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("build_seconds", std::to_string(seconds));
  EXPECT_GE(m.triangles.size(), 1000000u);
  EXPECT_EQ(m.triangles.size(), 1002252u);
  EXPECT_EQ(m.positions.size(), 501128u);
  expect_closed_manifold(m, "dense full size");
  expect_normals_agree_with_winding(m, "dense full size");
  // Unit sphere with bumps averaging out: volume near 4/3 π.
  EXPECT_NEAR(signed_volume(m), 4.0 / 3.0 * 3.14159265358979323846, 0.1);
}

TEST(SceneMeshes, ColumnIsClosedAndMadeOfSlivers) {
  scenegen::ColumnParams p;
  Mesh m = scenegen::make_column(p);
  EXPECT_EQ(m.triangles.size(), scenegen::column_triangle_count(p));
  expect_closed_manifold(m, "column");
  expect_normals_agree_with_winding(m, "column");
  EXPECT_NEAR(signed_volume(m) / (3.14159265358979323846 * p.radius * p.radius * p.height), 1.0, 0.01);
  // The side triangles are at least a thousand times longer than they are wide: longest edge
  // over the height onto it.
  const auto& t = m.triangles[2 * p.sides];  // past the bottom fan: the first of the band
  const glm::vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  const float height = glm::length(glm::cross(b - a, c - a)) / longest;
  EXPECT_GT(longest / height, 1000.0f);
}

TEST(SceneMeshes, DenseRoomHasAMillionTrianglesOfVeryDifferentSizes) {
  const scenegen::Document doc = scenegen::build_scene("dense_mesh");
  size_t triangles = 0;
  double smallest = 1e30, largest = 0.0;
  for (const auto& g : doc.meshes) {
    triangles += g.mesh.triangles.size();
    for (const auto& t : g.mesh.triangles) {
      const double area = 0.5 * glm::length(glm::cross(g.mesh.positions[t[1]] - g.mesh.positions[t[0]],
                                                       g.mesh.positions[t[2]] - g.mesh.positions[t[0]]));
      smallest = std::min(smallest, area), largest = std::max(largest, area);
    }
    // Every object is closed (the walls are single quads).
    if (g.mesh.triangles.size() > 2) expect_closed_manifold(g.mesh, g.name);
  }
  EXPECT_GE(triangles, 1000000u);
  EXPECT_LE(triangles, 1010000u);
  EXPECT_GE(doc.meshes.size(), 6u + 5u) << "the box's walls and at least five objects";
  // In each mesh's own coordinates (before node scales): still many orders of magnitude apart.
  EXPECT_GT(largest / smallest, 1e5);
}

}  // namespace
