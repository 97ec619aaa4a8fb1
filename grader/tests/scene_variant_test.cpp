// A scene's variant: the camera moved and turned, the free objects moved without leaving the room,
// the emitters and the room itself where they were, the lights' colours scaled; one key, one
// variant, another key, another.
#include "grader/scene_variant.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <pugixml.hpp>

#include "framework/scene/collada_loader.h"
#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"

namespace pt::grader {
namespace {

namespace fs = std::filesystem;

/// The numbers of the <translate> the variant put first in node `id`, or an empty list.
std::vector<double> shift_of(const pugi::xml_document& doc, const std::string& id) {
  pugi::xml_node node = doc.select_node(("//node[@id='" + id + "']").c_str()).node();
  pugi::xml_node first = node.first_child();
  std::vector<double> v;
  if (std::string(first.name()) != "translate") return v;
  std::istringstream in(first.child_value());
  for (double x; in >> x;) v.push_back(x);
  return v;
}

TEST(GraderSceneVariant, FreeObjectsMoveWithinTheRoomAndTheRoomStays) {
  test::TempFolder tmp("pt-variant");
  const std::string scene = (fs::path(test::source_dir()) / "scenes" / "cornell_spheres.dae").string();
  const std::string a = (tmp.path() / "a.dae").string(), b = (tmp.path() / "b.dae").string(),
                    again = (tmp.path() / "again.dae").string();
  const SceneVariant va = write_scene_variant(scene, 1, a);
  write_scene_variant(scene, 2, b);
  write_scene_variant(scene, 1, again);
  EXPECT_NE(va.description.find("Sphere1 moved"), std::string::npos) << va.description;
  pugi::xml_document da, db, dagain;
  ASSERT_TRUE(da.load_file(a.c_str()));
  ASSERT_TRUE(db.load_file(b.c_str()));
  ASSERT_TRUE(dagain.load_file(again.c_str()));
  for (const char* sphere : {"Sphere1", "Sphere2"}) {
    const std::vector<double> sa = shift_of(da, sphere), sb = shift_of(db, sphere);
    ASSERT_EQ(sa.size(), 3u) << sphere;
    ASSERT_EQ(sb.size(), 3u) << sphere;
    EXPECT_NE(sa, sb) << sphere << ": two keys, one placement";
    EXPECT_EQ(sa, shift_of(dagain, sphere)) << sphere << ": one key, two placements";
    // The room is about 2 across: no move beyond 2% of it.
    const double length = std::sqrt(sa[0] * sa[0] + sa[1] * sa[1] + sa[2] * sa[2]);
    EXPECT_GT(length, 0.0) << sphere;
    EXPECT_LE(length, std::sqrt(3.0) * 0.02 * 2.0 + 1e-9) << sphere;
  }
  // The room and the light's panel span the scene's box or emit: they stay.
  for (const char* fixed : {"floor", "ceiling", "leftWall", "rightWall", "backWall", "light"})
    EXPECT_TRUE(shift_of(da, fixed).empty()) << fixed << " was moved";
  // The variant is a scene the renderer reads.
  Scene loaded;
  ASSERT_NO_THROW(loaded = load_collada(a)) << a;
  EXPECT_EQ(loaded.spheres.size(), 2u);
}

TEST(GraderSceneVariant, AFileItCannotReadIsNamed) {
  test::TempFolder tmp("pt-variant");
  const std::string bad = (tmp.path() / "bad.dae").string();
  std::ofstream(bad) << "<COLLADA><library_visual_scenes>";
  try {
    write_scene_variant(bad, 1, (tmp.path() / "out.dae").string());
    FAIL() << "a malformed scene was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.dae"), std::string::npos) << e.what();
  }
  const std::string no_camera = (tmp.path() / "no_camera.dae").string();
  std::ofstream(no_camera) << "<COLLADA><library_visual_scenes><visual_scene/></library_visual_scenes></COLLADA>";
  try {
    write_scene_variant(no_camera, 1, (tmp.path() / "out.dae").string());
    FAIL() << "a scene with no camera was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_camera.dae: no <node> with an <instance_camera>"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace pt::grader
