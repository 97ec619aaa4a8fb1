// The committed scenes load with the framework's COLLADA reader as intended, and like the course's.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "framework/scene/collada_loader.h"
#include "framework/scene/scene.h"
#include "framework/testing/test_paths.h"

namespace {

std::string scene_path(const std::string& name) { return std::string(pt::test::source_dir()) + "/scenes/" + name + ".dae"; }

// Loads a committed scene and fails on any warning: our own files should need no fallback.
pt::Scene load(const std::string& name) {
  std::vector<std::string> warnings;
  pt::Scene s = pt::load_collada(scene_path(name), [&](const std::string& w) { warnings.push_back(w); });
  for (const std::string& w : warnings) ADD_FAILURE() << name << ": loader warned: " << w;
  return s;
}

const pt::Material* material_named(const pt::Scene& s, const std::string& name) {
  for (const pt::Material& m : s.materials)
    if (m.name == name) return &m;
  return nullptr;
}

// Every edge of the loaded triangles shared by exactly two of them: the file's vertex sharing
// survived loading, so a watertight intersection test leaves no crack.
uint64_t edges_not_shared_twice(const pt::Scene& s, uint32_t material) {
  std::vector<uint64_t> edges;
  for (const pt::Triangle& t : s.triangles) {
    if (t.material != material) continue;
    for (int k = 0; k < 3; ++k) {
      uint64_t a = t.v[k], b = t.v[(k + 1) % 3];
      edges.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  uint64_t bad = 0;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    bad += j - i != 2;
    i = j;
  }
  return bad;
}

// What every committed scene shares: the course's box, light and camera.
void expect_cornell_box(const pt::Scene& s, const std::string& name, float light_radiance = 10.0f) {
  SCOPED_TRACE(name);
  EXPECT_EQ(s.up_axis, "Z_UP");
  ASSERT_TRUE(s.has_camera);
  EXPECT_NEAR(s.camera.hfov_degrees, 49.13434f, 1e-4f);
  EXPECT_NEAR(s.camera.aspect, 4.0f / 3.0f, 1e-5f);
  glm::vec3 eye(s.camera.camera_to_world[3]);
  glm::vec3 forward = -glm::vec3(s.camera.camera_to_world[2]);
  EXPECT_NEAR(glm::distance(eye, glm::vec3(0, 3, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(glm::normalize(forward), glm::vec3(0, -1, 0)), 1.0f, 1e-6f) << "looks into the box";

  ASSERT_EQ(s.lights.size(), 1u);
  const pt::Light& l = s.lights[0];
  EXPECT_EQ(l.kind, pt::LightKind::area);
  EXPECT_EQ(l.radiance, glm::vec3(light_radiance));
  EXPECT_NEAR(glm::distance(l.position, glm::vec3(0, 0, 1.49f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(glm::cross(l.edge_u, l.edge_v)), 0.8f * 0.6f, 1e-6f) << "the panel's area";
  EXPECT_LT(glm::dot(l.direction, glm::vec3(0, 0, 1)), 0.0f) << "shines down";

  const pt::Material* panel = material_named(s, "light");
  ASSERT_NE(panel, nullptr);
  EXPECT_EQ(panel->emission, glm::vec3(10.0f));
  EXPECT_EQ(panel->kind, pt::MaterialKind::emission) << "the panel glows and reflects nothing";
  const pt::Material* left = material_named(s, "leftWall");
  ASSERT_NE(left, nullptr);
  EXPECT_EQ(left->albedo, glm::vec3(0.6f, 0.2f, 0.2f));

  pt::Bounds3 b = s.bounds();
  EXPECT_EQ(b.lo, glm::vec3(-1, -1, 0));
  EXPECT_EQ(b.hi, glm::vec3(1, 1, 1.5f));
}

TEST(SceneLoad, CornellEmpty) {
  pt::Scene s = load("cornell_empty");
  expect_cornell_box(s, "cornell_empty");
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(s.spheres.size(), 0u);
  EXPECT_EQ(s.materials.size(), 6u);
}

TEST(SceneLoad, CornellSpheres) {
  pt::Scene s = load("cornell_spheres");
  expect_cornell_box(s, "cornell_spheres");
  EXPECT_EQ(s.triangles.size(), 12u);
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_EQ(s.materials.size(), 7u);
  for (const pt::Sphere& sp : s.spheres) {
    EXPECT_EQ(sp.radius, 0.3f);
    EXPECT_EQ(sp.center.z, 0.3f) << "resting on the floor";
    EXPECT_EQ(s.materials[sp.material].kind, pt::MaterialKind::diffuse);
  }
}

TEST(SceneLoad, CornellMirrorGlass) {
  pt::Scene s = load("cornell_mirror_glass");
  expect_cornell_box(s, "cornell_mirror_glass");
  EXPECT_EQ(s.triangles.size(), 12u);
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_EQ(s.materials.size(), 8u);
  std::vector<pt::MaterialKind> kinds;
  for (const pt::Sphere& sp : s.spheres) kinds.push_back(s.materials[sp.material].kind);
  std::sort(kinds.begin(), kinds.end());
  EXPECT_EQ(kinds, (std::vector<pt::MaterialKind>{pt::MaterialKind::mirror, pt::MaterialKind::glass}));
  const pt::Material* glass = material_named(s, "glass");
  ASSERT_NE(glass, nullptr);
  EXPECT_EQ(glass->ior, 1.5f);
  EXPECT_EQ(glass->transmittance, glm::vec3(1.0f));
}

TEST(SceneLoad, CornellCoilStaysWatertight) {
  pt::Scene s = load("cornell_coil");
  expect_cornell_box(s, "cornell_coil");
  EXPECT_EQ(s.triangles.size(), 12u + 6368u);
  EXPECT_EQ(s.spheres.size(), 0u);
  EXPECT_EQ(s.materials.size(), 7u);
  EXPECT_EQ(s.normals.size(), s.positions.size()) << "the coil has per-vertex normals";
  const pt::Material* coil = material_named(s, "coil");
  ASSERT_NE(coil, nullptr);
  uint32_t id = uint32_t(coil - s.materials.data());
  EXPECT_EQ(std::count_if(s.triangles.begin(), s.triangles.end(),
                          [&](const pt::Triangle& t) { return t.material == id; }),
            6368);
  EXPECT_EQ(edges_not_shared_twice(s, id), 0u);
}

// CBcoil's situation: the light is half as bright as its panel and turned the other way round
// (0.6 × 0.8 under a 0.8 × 0.6 panel), and a mirror coil shows the panel to the camera.
TEST(SceneLoad, CornellMirrorCoilHasCBcoilsDisagreeingLight) {
  pt::Scene s = load("cornell_mirror_coil");
  expect_cornell_box(s, "cornell_mirror_coil", 5.0f);
  EXPECT_NEAR(glm::length(s.lights[0].edge_u), 0.6f, 1e-6f);
  EXPECT_NEAR(glm::length(s.lights[0].edge_v), 0.8f, 1e-6f);
  EXPECT_EQ(s.triangles.size(), 12u + 6368u);
  const pt::Material* coil = material_named(s, "chrome");
  ASSERT_NE(coil, nullptr);
  EXPECT_EQ(coil->kind, pt::MaterialKind::mirror);
  EXPECT_EQ(coil->reflectance, glm::vec3(0.95f));
}

// Our box frames like the course's: same camera, the same light, the box within the course's
// (whose exporter left a few millimetres of offset in its matrices).
TEST(SceneLoad, FramesLikeTheCourseScene) {
  const std::string course = std::string(pt::test::shared_scenes_dir()) + "/sky/CBspheres_lambertian.dae";
  if (!std::filesystem::exists(course)) GTEST_SKIP() << "the course's scenes are not at " << course;
  pt::Scene theirs = pt::load_collada(course, [](const std::string&) {});
  pt::Scene ours = load("cornell_spheres");
  ASSERT_TRUE(theirs.has_camera);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(ours.camera.camera_to_world[c][r], theirs.camera.camera_to_world[c][r], 1e-5f);
  EXPECT_EQ(ours.camera.hfov_degrees, theirs.camera.hfov_degrees);
  ASSERT_EQ(ours.lights.size(), theirs.lights.size());
  EXPECT_EQ(ours.lights[0].kind, theirs.lights[0].kind);
  EXPECT_EQ(ours.lights[0].radiance, theirs.lights[0].radiance);
  EXPECT_NEAR(glm::distance(ours.lights[0].position, theirs.lights[0].position), 0.0f, 0.01f);
  pt::Bounds3 a = ours.bounds(), b = theirs.bounds();
  EXPECT_NEAR(glm::distance(a.lo, b.lo), 0.0f, 0.01f);
  EXPECT_NEAR(glm::distance(a.hi, b.hi), 0.0f, 0.01f);
  EXPECT_EQ(ours.spheres.size(), theirs.spheres.size());
}

}  // namespace
