// Not needed for the assignment.
// The scene summary (pathtracer --info) and the one-line material fallback warning.
#include "framework/scene/scene_summary.h"

#include <string>

#include <gtest/gtest.h>

namespace pt {
namespace {

/// Two triangles (one emissive), a glass sphere, a mirror material nothing uses, two lights.
Scene small_scene() {
  Scene s;
  s.source = "small.dae";
  s.up_axis = "Z_UP";
  s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}};
  s.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  Material wall;
  wall.name = "wall";
  Material lamp;
  lamp.name = "lamp";
  lamp.emission = glm::vec3(10.0f);
  Material ball;
  ball.name = "ball";
  ball.kind = MaterialKind::glass;
  Material chrome;
  chrome.name = "chrome";
  chrome.kind = MaterialKind::mirror;
  s.materials = {wall, lamp, ball, chrome};
  s.triangles = {{{0, 1, 2}, 0}, {{0, 1, 3}, 1}};
  s.spheres = {{{0, 0, -3}, 0.5f, 2}};
  Light area;
  area.kind = LightKind::area;
  area.position = {0, 0, 1.5f};
  Light sky;
  sky.kind = LightKind::ambient;
  s.lights = {area, sky};
  s.has_camera = true;
  s.camera.camera_to_world[3] = glm::vec4(0, 3, 0, 1);
  s.camera.hfov_degrees = 40.0f;
  return s;
}

TEST(FrameworkSceneSummary, TextNamesEveryFact) {
  std::string text = describe_scene(small_scene());
  for (const char* want : {"small.dae", "Z_UP", "triangles:  2", "spheres:    1", "vertices:   4",
                           "diffuse 2: wall, lamp", "glass 1: ball", "mirror 1: chrome",
                           "emissive primitives: 1", "area radiance", "ambient radiance",
                           "(-0.5, -0.5, -3.5) to (1, 1, 2)", "(0, 3, 0)", "(0, 0, -1)", "hfov      40"})
    EXPECT_NE(text.find(want), std::string::npos) << "lacks \"" << want << "\" in:\n" << text;
}

TEST(FrameworkSceneSummary, JsonHoldsTheSameFacts) {
  nlohmann::json j = describe_scene_json(small_scene());
  EXPECT_EQ(j["file"], "small.dae");
  EXPECT_EQ(j["triangles"], 2);
  EXPECT_EQ(j["spheres"], 1);
  EXPECT_EQ(j["vertices"], 4);
  EXPECT_EQ(j["materials_by_kind"]["diffuse"], 2);
  EXPECT_EQ(j["materials_by_kind"]["glass"], 1);
  EXPECT_EQ(j["materials_by_kind"]["microfacet"], 0);
  EXPECT_EQ(j["materials"][1]["name"], "lamp");
  EXPECT_EQ(j["emissive_primitives"], 1);
  EXPECT_EQ(j["lights_by_kind"]["area"], 1);
  EXPECT_EQ(j["lights_by_kind"]["point"], 0);
  EXPECT_EQ(j["bounds"]["hi"][2], 2.0);
  EXPECT_EQ(j["camera"]["position"][1], 3.0);
  EXPECT_EQ(j["camera"]["direction"][2], -1.0);
  EXPECT_EQ(j["camera"]["hfov_degrees"], 40.0);
  EXPECT_TRUE(j["camera"]["from_file"]);
}

TEST(FrameworkSceneSummary, FallbackWarningNamesWhatIsDrawnAsDiffuse) {
  Scene s = small_scene();
  std::string line = materials_falling_back(s, {MaterialKind::diffuse});
  EXPECT_EQ(line.find('\n'), std::string::npos) << "one line";
  EXPECT_NE(line.find("ball (glass)"), std::string::npos) << line;
  EXPECT_NE(line.find("chrome (mirror)"), std::string::npos) << line;
  EXPECT_EQ(line.find("wall"), std::string::npos) << line;
  line = materials_falling_back(s, {MaterialKind::diffuse, MaterialKind::mirror});
  EXPECT_NE(line.find("ball (glass)"), std::string::npos) << line;
  EXPECT_EQ(line.find("chrome"), std::string::npos) << line;
  EXPECT_EQ(materials_falling_back(s, {MaterialKind::diffuse, MaterialKind::mirror, MaterialKind::glass}), "");
}

}  // namespace
}  // namespace pt
