// The committed scenes are exactly what the generator writes, so nobody edits them by hand.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/testing/test_paths.h"
#include "framework/text/text_file.h"
#include "scenes/generator/collada_writer.h"
#include "scenes/generator/cornell_scenes.h"

namespace {

// The first line where two texts differ, for a message that says where to look.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool ga = bool(std::getline(sa, la)), gb = bool(std::getline(sb, lb));
    if (!ga && !gb) return "no line differs (line endings?)";
    if (!ga || !gb || la != lb)
      return "line " + std::to_string(line) + ":\n  file:      " + la.substr(0, 160) +
             "\n  generator: " + lb.substr(0, 160);
  }
}

TEST(SceneFiles, CommittedScenesAreWhatTheGeneratorWrites) {
  int committed = 0;
  for (const auto& entry : scenegen::scene_entries()) {
    if (!entry.committed) continue;
    ++committed;
    const std::string path = std::string(pt::test::source_dir()) + "/scenes/" + entry.name + ".dae";
    const std::string on_disk = pt::read_text_file(path);
    ASSERT_FALSE(on_disk.empty()) << path << " is missing or empty";
    const std::string generated = scenegen::to_collada(scenegen::build_scene(entry.name));
    EXPECT_TRUE(on_disk == generated)
        << path << " differs from what scene_gen writes at " << first_difference(on_disk, generated)
        << "\nChange the generator, not the file, then: cmake --build <build> --target regenerate_scenes";
  }
  EXPECT_EQ(committed, 7);
}

TEST(SceneFiles, OutputIsDeterministic) {
  for (const auto& entry : scenegen::scene_entries()) {
    if (!entry.committed) continue;
    EXPECT_EQ(scenegen::to_collada(scenegen::build_scene(entry.name)),
              scenegen::to_collada(scenegen::build_scene(entry.name)))
        << entry.name;
  }
}

TEST(SceneFiles, FloatsRoundTripExactly) {
  for (float v : {0.3f, 1.49f, -0.4f, 1.0f / 3.0f, 1e-7f, 3.4e38f, 1.17549435e-38f, 0.0999999940f}) {
    std::string text = scenegen::format_float(v);
    EXPECT_EQ(std::stof(text), v) << text;
  }
  EXPECT_EQ(scenegen::format_float(-0.0f), "0");
  EXPECT_EQ(scenegen::format_float(0.3f), "0.3");
}

TEST(SceneFiles, WriterRejectsBrokenReferences) {
  scenegen::Document doc = scenegen::cornell_box();
  doc.nodes.push_back({"ghost", glm::mat4(1.0f), scenegen::Node::Kind::geometry, "nothing", "floor"});
  EXPECT_THROW(scenegen::to_collada(doc), std::invalid_argument);

  doc = scenegen::cornell_box();
  doc.nodes.back().material = "no-such-material";
  EXPECT_THROW(scenegen::to_collada(doc), std::invalid_argument);

  doc = scenegen::cornell_box();
  doc.meshes.front().mesh.triangles.front()[1] = 99;
  EXPECT_THROW(scenegen::to_collada(doc), std::invalid_argument);

  doc = scenegen::cornell_box();
  doc.meshes.front().mesh.positions.front().x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(scenegen::to_collada(doc), std::invalid_argument);

  EXPECT_THROW(scenegen::build_scene("cornell_nothing"), std::invalid_argument);
}

}  // namespace
