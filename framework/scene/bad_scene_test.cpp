// Not needed for the assignment.
// Broken scene files: each gets a SceneError naming the file, the element and what is wrong;
// none crashes or hangs, however it is cut.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"
#include "framework/testing/scene_error_of.h"
#include "framework/testing/test_paths.h"

namespace pt {
namespace {

/// A small valid scene; the tests break one thing in it at a time.
std::string scene_with(const std::string& array = "0 0 0 1 0 0 0 1 0 1 1 0",
                       const std::string& p = "0 1 2 2 1 3",
                       const std::string& extra_geometry = "",
                       const std::string& nodes = "<node id=\"N\"><instance_geometry url=\"#g\"/></node>") {
  return R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_geometries>
    <geometry id="g">
      <mesh>
        <source id="g-pos">
          <float_array id="g-pos-a" count="12">)" + array + R"(</float_array>
          <technique_common><accessor source="#g-pos-a" count="4" stride="3"/></technique_common>
        </source>
        <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
        <triangles count="2">
          <input semantic="VERTEX" source="#g-v" offset="0"/>
          <p>)" + p + R"(</p>
        </triangles>
      </mesh>
    </geometry>)" + extra_geometry + R"(
  </library_geometries>
  <library_cameras><camera id="cam"><optics><technique_common><perspective><xfov>40</xfov>
  </perspective></technique_common></optics></camera></library_cameras>
  <library_visual_scenes>
    <visual_scene id="vs">
      <node id="Eye"><translate>0 0 5</translate><instance_camera url="#cam"/></node>
      )" + nodes + R"(
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#vs"/></scene>
</COLLADA>
)";
}

/// Loads `xml` as `name` and returns the error message; fails the test if it loads.
std::string error_of(const std::string& xml, const std::string& name = "broken.dae") {
  return pt::error_of(xml, name);
}

#define EXPECT_MENTIONS(msg, text) \
  EXPECT_NE((msg).find(text), std::string::npos) << "message: " << (msg) << "\nlacks: " << (text)

TEST(FrameworkBadScene, TheValidBaseSceneLoads) {
  Scene s = load_collada_string(scene_with(), "ok.dae", [](const std::string& w) { ADD_FAILURE() << w; });
  EXPECT_EQ(s.triangles.size(), 2u);
  EXPECT_TRUE(s.has_camera);
}

TEST(FrameworkBadScene, MissingFile) {
  std::string path = std::string(pt::test::binary_dir()) + "/no-such-scene.dae";
  try {
    load_collada(path);
    FAIL() << "loaded a file that does not exist";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_MENTIONS(std::string(e.what()), path);
    EXPECT_MENTIONS(std::string(e.what()), "no such file");
  }
}

TEST(FrameworkBadScene, DirectoryInsteadOfFile) {
  try {
    load_collada(pt::test::binary_dir());
    FAIL() << "loaded a directory";
  } catch (const SceneError& e) {
    EXPECT_MENTIONS(std::string(e.what()), "directory");
  }
}

TEST(FrameworkBadScene, FileOnDiskWithLineNumber) {
  // Through a real file, so that load_collada's own reading is on the path.
  std::string path = std::string(pt::test::binary_dir()) + "/bad_scene_test_nan.dae";
  std::string xml = scene_with("0 0 0 1 0 0 0 nan 0 1 1 0");
  std::ofstream(path) << xml;
  try {
    load_collada(path);
    FAIL() << "loaded a NaN";
  } catch (const SceneError& e) {
    std::string msg = e.what();
    EXPECT_MENTIONS(msg, path);
    EXPECT_MENTIONS(msg, "<float_array id=\"g-pos-a\">");
    EXPECT_MENTIONS(msg, "(line 7)");  // the line the array is on in scene_with()
    EXPECT_MENTIONS(msg, "\"nan\"");
  }
  std::filesystem::remove(path);
}

TEST(FrameworkBadScene, NotXml) {
  std::string msg = error_of("this is not a scene, just words", "words.dae");
  EXPECT_MENTIONS(msg, "words.dae");
  EXPECT_MENTIONS(msg, "not XML");
  msg = error_of("<COLLADA><library_geometries></COLLADA>", "tags.dae");
  EXPECT_MENTIONS(msg, "tags.dae");
  EXPECT_MENTIONS(msg, "<library_geometries>");
  EXPECT_MENTIONS(msg, "XML");
  msg = error_of("<?xml version=\"1.0\"?><scene><thing/></scene>", "other.dae");
  EXPECT_MENTIONS(msg, "<scene>");
  EXPECT_MENTIONS(msg, "not <COLLADA>");
}

TEST(FrameworkBadScene, TruncatedXml) {
  std::string xml = scene_with();
  std::string cut = xml.substr(0, xml.find("<p>") + 8);
  std::string msg = error_of(cut, "cut.dae");
  EXPECT_MENTIONS(msg, "cut.dae");
  EXPECT_MENTIONS(msg, "truncated");
  EXPECT_MENTIONS(msg, "<p>");  // the innermost element still open
}

TEST(FrameworkBadScene, IndexOutOfRange) {
  std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 7"));
  EXPECT_MENTIONS(msg, "broken.dae");
  EXPECT_MENTIONS(msg, "<p> in <triangles> in <mesh> in <geometry id=\"g\">");
  EXPECT_MENTIONS(msg, "index 7");
  EXPECT_MENTIONS(msg, "count 4");
}

TEST(FrameworkBadScene, TooFewIndices) {
  std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1"));
  EXPECT_MENTIONS(msg, "<p> in <triangles>");
  EXPECT_MENTIONS(msg, "holds 5 indices");
}

TEST(FrameworkBadScene, DanglingUrl) {
  std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", "",
                                        "<node id=\"N\"><instance_geometry url=\"#nowhere\"/></node>"));
  EXPECT_MENTIONS(msg, "<instance_geometry url=\"#nowhere\">");
  EXPECT_MENTIONS(msg, "node id=\"N\"");
  EXPECT_MENTIONS(msg, "points nowhere");
  std::string xml = scene_with();
  xml.replace(xml.find("#g-pos-a"), 8, "#missing");
  msg = error_of(xml);
  EXPECT_MENTIONS(msg, "<accessor");
  EXPECT_MENTIONS(msg, "#missing");
}

TEST(FrameworkBadScene, NanInfAndTextWhereANumberBelongs) {
  for (const char* bad : {"nan", "inf", "-infinity", "1e999", "abc", "1.0x", "1,5"}) {
    std::string msg = error_of(scene_with(std::string("0 0 0 1 0 0 ") + bad + " 1 0 1 1 0"));
    EXPECT_MENTIONS(msg, "broken.dae");
    EXPECT_MENTIONS(msg, "<float_array id=\"g-pos-a\">");
    EXPECT_MENTIONS(msg, "value 6");
  }
  std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 two 2 1 3"));
  EXPECT_MENTIONS(msg, "<p>");
  EXPECT_MENTIONS(msg, "\"two\"");
  msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 -2 2 1 3"));
  EXPECT_MENTIONS(msg, "<p>");
  EXPECT_MENTIONS(msg, "-2");
  msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", "",
                            "<node id=\"N\"><translate>1 NaN 0</translate><instance_geometry url=\"#g\"/></node>"));
  EXPECT_MENTIONS(msg, "<translate> in <node id=\"N\">");
}

TEST(FrameworkBadScene, ArrayShorterThanItsAccessor) {
  std::string xml = scene_with("0 0 0 1 0 0 0 1 0");
  xml.replace(xml.find("count=\"12\""), 10, "count=\"9\"");
  std::string msg = error_of(xml);
  EXPECT_MENTIONS(msg, "<accessor");
  EXPECT_MENTIONS(msg, "source id=\"g-pos\"");
  EXPECT_MENTIONS(msg, "needs 12");
  EXPECT_MENTIONS(msg, "only 9");
  // And an array that holds fewer numbers than its own count says.
  msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1"));
  EXPECT_MENTIONS(msg, "<float_array id=\"g-pos-a\">");
  EXPECT_MENTIONS(msg, "holds 11");
}

TEST(FrameworkBadScene, EmptyScene) {
  std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", "", "<node id=\"lonely\"/>"));
  EXPECT_MENTIONS(msg, "broken.dae");
  EXPECT_MENTIONS(msg, "<visual_scene id=\"vs\">");
  EXPECT_MENTIONS(msg, "nothing to render");
}

TEST(FrameworkBadScene, SphereRadiusNotPositive) {
  for (const char* r : {"0", "-1"}) {
    std::string sphere = std::string("<geometry id=\"ball\"><extra><technique profile=\"CGL\"><sphere><radius>") + r +
                         "</radius></sphere></technique></extra></geometry>";
    std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", sphere,
                                          "<node id=\"S\"><instance_geometry url=\"#ball\"/></node>"));
    EXPECT_MENTIONS(msg, "<radius> in <sphere>");
    EXPECT_MENTIONS(msg, "geometry id=\"ball\"");
    EXPECT_MENTIONS(msg, "not positive");
  }
  // A zero scale on the node collapses a valid sphere.
  std::string sphere = "<geometry id=\"ball\"><extra><technique profile=\"CGL\"><sphere><radius>1</radius>"
                       "</sphere></technique></extra></geometry>";
  std::string msg = error_of(scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", sphere,
                                        "<node id=\"S\"><scale>0 0 0</scale><instance_geometry url=\"#ball\"/></node>"));
  EXPECT_MENTIONS(msg, "<instance_geometry url=\"#ball\">");
}

TEST(FrameworkBadScene, ZeroAreaLight) {
  std::string light = "<library_lights><light id=\"L\"><extra><technique profile=\"CGL\"><area><color>1 1 1</color>"
                      "</area></technique></extra></light></library_lights>";
  std::string xml = scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", "",
                               "<node id=\"N\"><instance_geometry url=\"#g\"/></node>"
                               "<node id=\"Lamp\"><scale>1 0 1</scale><instance_light url=\"#L\"/></node>");
  xml.replace(xml.find("<library_visual_scenes>"), 0, light);
  std::string msg = error_of(xml);
  EXPECT_MENTIONS(msg, "node id=\"Lamp\"");
  EXPECT_MENTIONS(msg, "zero area");
}

TEST(FrameworkBadScene, UnknownElementsAreWarnedAndSkipped) {
  std::string xml = scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3", "<nurbs_thing id=\"x\"/>",
                               "<node id=\"N\"><wobble/><instance_geometry url=\"#g\"/></node><gizmo/>");
  std::vector<std::string> warnings;
  Scene s = load_collada_string(xml, "odd.dae", [&](const std::string& w) { warnings.push_back(w); });
  EXPECT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_MENTIONS(warnings[0], "odd.dae");
  EXPECT_MENTIONS(warnings[0], "<nurbs_thing id=\"x\">");
  EXPECT_MENTIONS(warnings[1], "<wobble> in <node id=\"N\">");
  EXPECT_MENTIONS(warnings[2], "<gizmo>");
  for (const std::string& w : warnings) EXPECT_MENTIONS(w, "skipped");
}

TEST(FrameworkBadScene, EveryTruncationFailsCleanly) {
  // Cut the scene at every byte: each prefix either loads (never, here, since </COLLADA> is
  // needed) or throws SceneError naming the file; nothing else may escape, nothing may hang.
  std::string xml = scene_with();
  size_t errors = 0;
  for (size_t n = 0; n < xml.size() - 12; ++n) {
    try {
      load_collada_string(xml.substr(0, n), "prefix.dae", [](const std::string&) {});
    } catch (const SceneError& e) {
      ++errors;
      ASSERT_EQ(std::string(e.what()).rfind("prefix.dae: ", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(errors, xml.size() - 12);
}

TEST(FrameworkBadScene, RandomCorruptionsFailCleanly) {
  // Seeded (fixed) corruptions of a valid scene: a few characters replaced by ones that matter
  // to XML or to numbers. Each must load or throw SceneError; nothing else (no bad_alloc, no
  // out_of_range, no crash) may escape.
  std::string base = scene_with("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 2 1 3",
                                "<geometry id=\"ball\"><extra><technique profile=\"CGL\"><sphere><radius>1"
                                "</radius></sphere></technique></extra></geometry>",
                                "<node id=\"N\"><rotate>0 0 1 30</rotate><instance_geometry url=\"#g\"/>"
                                "<instance_geometry url=\"#ball\"/></node>");
  const std::string alphabet = "<>/\"= #-.e9017x&;";
  std::mt19937 rng(20240601u);
  size_t loaded = 0, refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string xml = base;
    int edits = 1 + int(rng() % 3);
    for (int e = 0; e < edits; ++e) xml[rng() % xml.size()] = alphabet[rng() % alphabet.size()];
    try {
      Scene s = load_collada_string(xml, "mutant.dae", [](const std::string&) {});
      ASSERT_GT(s.primitive_count(), 0u);
      ++loaded;
    } catch (const SceneError& e) {
      ASSERT_EQ(std::string(e.what()).rfind("mutant.dae: ", 0), 0u) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 0u);
  EXPECT_GT(loaded, 0u);
}

}  // namespace
}  // namespace pt
