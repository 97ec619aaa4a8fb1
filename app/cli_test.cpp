// The pathtracer command end to end: help, every kind of bad input, and small real renders.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/image/estimate_exr.h"
#include "framework/image/image.h"

namespace fs = std::filesystem;

namespace {

// Two triangles (a unit quad at z = -2, facing the camera) and a camera at the origin looking
// down -Z with a 2:1 aspect, so the default resolution is 480 x 240.
const char* kQuadScene = R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Y_UP</up_axis></asset>
  <library_cameras>
    <camera id="cam"><optics><technique_common><perspective>
      <xfov>60</xfov><aspect_ratio>2</aspect_ratio><znear>0.1</znear><zfar>100</zfar>
    </perspective></technique_common></optics></camera>
  </library_cameras>
  <library_geometries>
    <geometry id="quad"><mesh>
      <source id="quad-pos"><float_array id="quad-pos-a" count="12">-1 -1 -2 1 -1 -2 1 1 -2 -1 1 -2</float_array>
        <technique_common><accessor source="#quad-pos-a" count="4" stride="3"/></technique_common></source>
      <vertices id="quad-v"><input semantic="POSITION" source="#quad-pos"/></vertices>
      <triangles count="2"><input semantic="VERTEX" source="#quad-v" offset="0"/><p>0 1 2 0 2 3</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene">
      <node id="camera"><instance_camera url="#cam"/></node>
      <node id="quad"><instance_geometry url="#quad"/></node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

struct Outcome {
  int exit_code = -1;
  bool crashed = false;
  std::string out, err;
};

std::string quote(const std::string& s) { return "'" + s + "'"; }

/// A temporary folder holding the quad scene, removed at the end.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pt_cli_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(scene()) << kQuadScene;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string scene() const { return (dir_ / "quad.dae").string(); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs the pathtracer with `args` (shell words) in the temporary folder, with the
  /// environment's assignments `env` (shell words, "NAME=value ...") added.
  Outcome pathtracer(const std::string& args, const std::string& env = "") const {
    const std::string binary = PT_PATHTRACER;
    const std::string err_file = file("stderr.txt");
    std::string command = "cd " + quote(dir_.string()) + " && " + env + " " + quote(binary) + " " +
                          args + " 2>" + quote(err_file);
    Outcome run;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
      ADD_FAILURE() << "popen failed: " << command;
      return run;
    }
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
    int status = pclose(pipe);
    run.crashed = WIFSIGNALED(status);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err_file);
    run.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return run;
  }

  fs::path dir_;
};

}  // namespace

TEST_F(CliTest, HelpListsTheCourseFlagsAndExitsZero) {
  Outcome run = pathtracer("--help");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  for (const char* flag : {"--samples", "--light-samples", "--threads", "--max-depth", "--resolution",
                           "--file", "--hemisphere", "--adaptive", "--env", "--aperture",
                           "--focal-distance", "--cell", "--info", "--seed", "--bvh", "--bvh-width", "--leaf-size",
                           "--normals", "--integrator", "--file-camera", "--course-view", "--stopping-rule",
                           "--camera-settings", "--accumulate-bounces", "--camera"})
    EXPECT_NE(run.out.find(flag), std::string::npos) << flag << " missing from:\n" << run.out;
}

TEST_F(CliTest, BadInputIsNamedAndNeverACrash) {
  struct Case {
    std::string args;
    int exit_code;
    std::string must_mention;
  };
  const std::string s = quote(scene());
  const Case cases[] = {
      {"-s 0 -f a.png " + s, 2, "--samples"},
      {"-s -3 -f a.png " + s, 2, "--samples"},
      {"-r 0 10 -f a.png " + s, 2, "--resolution"},
      {"-r 100000 10 -f a.png " + s, 2, "--resolution"},
      {"-r 10 -f a.png " + s, 2, "resolution"},              // one number where two are needed
      {"-r 40 30 -p 30 0 20 10 -f a.png " + s, 2, "--cell"},   // past the right edge
      {"-r 40 30 -p -1 0 5 5 -f a.png " + s, 2, "--cell"},
      {"-p 0 0 481 1 -f a.png " + s, 2, "--cell"},             // default 480 wide
      {"-t -1 -f a.png " + s, 2, "--threads"},
      {"-m -1 -f a.png " + s, 2, "--max-depth"},
      {"-a 0 0.05 -f a.png " + s, 2, "--adaptive"},
      {"-a 16 0 -f a.png " + s, 2, "--adaptive"},
      {"-a 16 0.05 --stopping-rule fair -f a.png " + s, 2, "--stopping-rule"},
      {"--stopping-rule course -f a.png " + s, 2, "--stopping-rule"},  // no -a: nothing to stop
      {"-d 0 -f a.png " + s, 2, "--focal-distance"},
      {"--bvh octree -f a.png " + s, 2, "--bvh"},
      {"--bvh-width 3 -f a.png " + s, 2, "--bvh-width"},
      {"--bvh-width 4 -f a.png " + s, 2, "--bvh-width"},  // the wide tree has eight children
      {"--frobnicate -f a.png " + s, 2, "--frobnicate"},
      {"-s many -f a.png " + s, 2, "many"},
      {"-f a.png", 2, "scene"},                                // no scene at all
      {"-f a.png " + quote(file("absent.dae")), 1, "absent.dae"},
      {"-f " + quote(file("no/such/folder/a.png")) + " " + s, 1, "no/such/folder"},
      {"-f a.jpg " + s, 2, "a.jpg"},
      {"-f a " + s, 2, "extension"},
      {"-e " + quote(file("missing.exr")) + " -f a.png " + s, 1, "missing.exr"},
      {"--integrator photon -f a.png " + s, 2, "--integrator"},
      {"--integrator direct -m 3 -f a.png " + s, 2, "-m 3"},   // direct light stops at -m 1
      {"--integrator direct --mis -f a.png " + s, 2, "--mis"},  // MIS is Part 4's
      {"--normals --integrator path -f a.png " + s, 2, "--normals"},
      {"--course-view --file-camera -f a.png " + s, 2, "--file-camera"},  // two placements
      {"--camera 0,0,0,0,0,-1,0,1,0 -f a.png " + s, 2, "ten numbers"},      // nine
      {"--camera 0,0,0,0,0,-1,0,1,0,60,1 -f a.png " + s, 2, "ten numbers"}, // eleven
      {"--camera 0,0,0,0,0,-1,0,1,0,wide -f a.png " + s, 2, "fov"},
      {"--camera 0,0,x,0,0,-1,0,1,0,60 -f a.png " + s, 2, "pz"},
      {"--camera 0,0,0,0,0,-1,0,1,0,nan -f a.png " + s, 2, "fov"},
      {"--camera 0,0,1e39,0,0,-1,0,1,0,60 -f a.png " + s, 2, "pz"},       // overflows a float
      {"--camera ,0,0,0,0,-1,0,1,0,60 -f a.png " + s, 2, "px"},
      {"--camera 1,2,3,1,2,3,0,1,0,60 -f a.png " + s, 2, "same point"},
      {"--camera 0,0,0,0,0,-1,0,0,0,60 -f a.png " + s, 2, "up direction"},
      {"--camera 0,0,0,0,0,-1,0,0,2,60 -f a.png " + s, 2, "along the direction of view"},
      {"--camera 0,0,0,0,0,-1,0,1,0,0 -f a.png " + s, 2, "field of view"},
      {"--camera 0,0,0,0,0,-1,0,1,0,180 -f a.png " + s, 2, "field of view"},
      {"--camera 0,0,0,0,0,-1,0,1,0,60 --file-camera -f a.png " + s, 2, "--file-camera"},
      {"--camera 0,0,0,0,0,-1,0,1,0,60 --course-view -f a.png " + s, 2, "--course-view"},
  };
  for (const Case& c : cases) {
    Outcome run = pathtracer(c.args);
    EXPECT_FALSE(run.crashed) << c.args;
    EXPECT_EQ(run.exit_code, c.exit_code) << c.args << "\n" << run.err;
    EXPECT_NE(run.err.find(c.must_mention), std::string::npos)
        << c.args << ": the message does not name '" << c.must_mention << "':\n" << run.err;
    EXPECT_EQ(run.err.find("terminate"), std::string::npos) << c.args << "\n" << run.err;
  }
  EXPECT_FALSE(fs::exists(file("a.png")));  // no bad command line rendered anything
}

// --camera places the camera where it says: the quad scene's own camera (at the origin, looking
// down -Z, 60 degrees) given by --camera renders the file camera's image to the byte, and a camera
// turned to look away from the quad sees nothing of it.
TEST_F(CliTest, CameraOptionPlacesTheCamera) {
  const std::string s = quote(scene());
  ASSERT_EQ(pathtracer("--normals -r 40 20 --file-camera -f file.png " + s).exit_code, 0);
  Outcome same = pathtracer("--normals -r 40 20 --camera 0,0,0,0,0,-1,0,1,0,60 -f same.png " + s);
  ASSERT_EQ(same.exit_code, 0) << same.err;
  const pt::Image a = pt::read_image(file("file.png")), b = pt::read_image(file("same.png"));
  ASSERT_EQ(a.pixels().size(), b.pixels().size());
  EXPECT_TRUE(a.pixels() == b.pixels()) << "--camera at the file's own camera drew another image";
  EXPECT_NEAR(b.at(20, 10).z, 1.0f, 0.01f);  // the quad, facing the camera

  Outcome away = pathtracer("--normals -r 40 20 --camera 0,0,0,0,0,1,0,1,0,60 -f away.png " + s);
  ASSERT_EQ(away.exit_code, 0) << away.err;
  const pt::Image c = pt::read_image(file("away.png"));
  for (const glm::vec3& v : c.pixels()) ASSERT_EQ(v, glm::vec3(0.0f)) << "looking away, yet a hit";

  // Off to the side (eye at x = 0.6, looking straight down -Z): the image spans x from -0.55 to
  // 1.75 at the quad, whose right edge (x = 1) is then two thirds of the way across.
  Outcome side = pathtracer("--normals -r 40 20 --camera 0.6,0,0,0.6,0,-1,0,1,0,60 -f side.png " + s);
  ASSERT_EQ(side.exit_code, 0) << side.err;
  const pt::Image d = pt::read_image(file("side.png"));
  EXPECT_NEAR(d.at(10, 10).z, 1.0f, 0.01f);      // left of centre: the quad
  EXPECT_EQ(d.at(39, 10), glm::vec3(0.0f));      // far right: past its edge
}

TEST_F(CliTest, BrokenSceneFileIsAnInputError) {
  std::ofstream(file("broken.dae")) << "<COLLADA><library_geometries>";
  Outcome run = pathtracer("-f a.png " + quote(file("broken.dae")));
  EXPECT_FALSE(run.crashed);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("broken.dae"), std::string::npos) << run.err;
}

TEST_F(CliTest, TinyRenderWritesAPngOfTheRequestedSize) {
  Outcome run = pathtracer("--normals -r 40 30 -s 2 -t 2 -f out.png " + quote(scene()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("render: 40x30, 2 spp"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("rays/s"), std::string::npos) << run.out;
  pt::Image image = pt::read_image(file("out.png"));
  EXPECT_EQ(image.width(), 40);
  EXPECT_EQ(image.height(), 30);
  // The quad covers the centre, facing the camera: normal (0,0,1) shows as (0.5, 0.5, 1).
  glm::vec3 centre = image.at(20, 15);
  EXPECT_NEAR(centre.x, 0.5f, 0.01f);
  EXPECT_NEAR(centre.y, 0.5f, 0.01f);
  EXPECT_NEAR(centre.z, 1.0f, 0.01f);
  EXPECT_EQ(image.at(0, 0), glm::vec3(0.0f));  // a corner sees past the quad: black
}

TEST_F(CliTest, WithoutFileWritesSceneStemPngAtTheSceneAspect) {
  Outcome run = pathtracer("--normals " + quote(scene()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("quad.png"), std::string::npos) << run.out;
  pt::Image image = pt::read_image(file("quad.png"));
  EXPECT_EQ(image.width(), 480);
  EXPECT_EQ(image.height(), 240);  // 480 / the camera's aspect of 2
}

TEST_F(CliTest, ExrCarriesVarianceAndCountAndCellOnlyRendersTheCell) {
  Outcome run = pathtracer("--normals -r 40 30 -s 3 -p 5 7 11 4 -f out.exr " + quote(scene()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  pt::RenderEstimate e = pt::read_estimate_exr(file("out.exr"));
  ASSERT_EQ(e.width, 40);
  ASSERT_EQ(e.height, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      bool inside = x >= 5 && x < 16 && y >= 7 && y < 11;
      ASSERT_EQ(e.count[size_t(y) * 40 + size_t(x)], inside ? 3.0f : 0.0f) << x << "," << y;
    }
}

TEST_F(CliTest, SameSeedSameImageWithOneOrTwoThreads) {
  const std::string common = "--normals -r 32 24 -s 4 --seed 7 " + quote(scene());
  ASSERT_EQ(pathtracer("-t 1 -f one.exr " + common).exit_code, 0);
  ASSERT_EQ(pathtracer("-t 2 -f two.exr " + common).exit_code, 0);
  pt::RenderEstimate one = pt::read_estimate_exr(file("one.exr"));
  pt::RenderEstimate two = pt::read_estimate_exr(file("two.exr"));
  EXPECT_EQ(one.mean, two.mean);
  EXPECT_EQ(one.variance, two.variance);
}

TEST_F(CliTest, InfoDescribesTheSceneWithoutRendering) {
  Outcome run = pathtracer("--info " + quote(scene()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("triangles"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("render:"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(file("quad.png")));
}

// The image library (OpenImageIO and its 260-odd shared objects) is opened only to read or write
// an image: the dynamic loader's own log (LD_DEBUG=files, on stderr) says what a command brought in.
TEST_F(CliTest, CommandsThatWriteNoImageNeverLoadTheImageLibrary) {
  for (const std::string& args : {std::string("--help"), "--info " + quote(scene())}) {
    Outcome run = pathtracer(args, "LD_DEBUG=files");
    ASSERT_EQ(run.exit_code, 0) << args << ": " << run.err;
    ASSERT_NE(run.err.find("generating link map"), std::string::npos)
        << "the loader's log is empty: " << run.err;
    EXPECT_EQ(run.err.find("OpenImageIO"), std::string::npos) << args << " loaded it:\n" << run.err;
    EXPECT_EQ(run.err.find("pt_image_oiio"), std::string::npos) << args << " loaded it";
  }
  // A render loads it to write its image.
  Outcome render = pathtracer("--normals -r 8 6 -s 1 -f out.png " + quote(scene()), "LD_DEBUG=files");
  ASSERT_EQ(render.exit_code, 0) << render.err;
  EXPECT_NE(render.err.find("pt_image_oiio"), std::string::npos) << render.err;
  EXPECT_TRUE(fs::exists(file("out.png")));
}

TEST_F(CliTest, AMissingImageModuleIsNamedWithThePlacesLookedIn) {
  Outcome run = pathtracer("--normals -r 8 6 -s 1 -f lost.png " + quote(scene()),
                           "PT_IMAGE_MODULE_DIR=" + quote(file("nowhere")));
  EXPECT_FALSE(run.crashed);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("lost.png"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("pt_image_oiio.so"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nowhere"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(file("lost.png")));
}

// The quad scene lit by a point light behind the camera, so an image says what the flags did.
std::string lit_quad_scene() {
  std::string s = kQuadScene;
  s.insert(s.find("  <library_cameras>"),
           "  <library_lights><light id=\"lamp\"><technique_common><point><color>3 3 3</color>"
           "</point></technique_common></light></library_lights>\n");
  s.insert(s.find("      <node id=\"quad\">"),
           "      <node id=\"lamp\"><translate>0.3 0.2 1</translate><instance_light url=\"#lamp\"/></node>\n");
  return s;
}

bool same_pixels(const pt::Image& a, const pt::Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (a.at(x, y) != b.at(x, y)) return false;
  return true;
}

// A floor under a CGL area light (0.6 × 0.8, z = 1, shining down) whose emissive panel is
// 0.8 × 0.6: the course's Cornell boxes' light, in miniature.
const char* kPanelUnlikeItsLight = R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Z_UP</up_axis></asset>
  <library_lights><light id="lamp" name="Lamp"><technique_common><point><color>5 5 5</color></point></technique_common>
    <extra><technique profile="CGL"><area><color>5 5 5</color></area></technique></extra></light></library_lights>
  <library_effects>
    <effect id="glow-fx"><profile_COMMON><technique sid="common"><phong><diffuse><color>0.8 0.8 0.8 1</color></diffuse></phong></technique></profile_COMMON>
      <extra><technique profile="CGL"><emission><radiance>5 5 5</radiance></emission></technique></extra></effect>
    <effect id="grey-fx"><profile_COMMON><technique sid="common"><phong><diffuse><color>0.5 0.5 0.5 1</color></diffuse></phong></technique></profile_COMMON></effect>
  </library_effects>
  <library_materials><material id="glow" name="glow"><instance_effect url="#glow-fx"/></material>
    <material id="grey" name="grey"><instance_effect url="#grey-fx"/></material></library_materials>
  <library_geometries>
    <geometry id="panel"><mesh>
      <source id="panel-p"><float_array id="panel-pa" count="12">-0.4 -0.3 1 0.4 -0.3 1 0.4 0.3 1 -0.4 0.3 1</float_array>
        <technique_common><accessor source="#panel-pa" count="4" stride="3"/></technique_common></source>
      <vertices id="panel-v"><input semantic="POSITION" source="#panel-p"/></vertices>
      <triangles material="glow" count="2"><input semantic="VERTEX" source="#panel-v" offset="0"/><p>0 2 1 0 3 2</p></triangles>
    </mesh></geometry>
    <geometry id="floor"><mesh>
      <source id="floor-p"><float_array id="floor-pa" count="12">-2 -2 0 2 -2 0 2 2 0 -2 2 0</float_array>
        <technique_common><accessor source="#floor-pa" count="4" stride="3"/></technique_common></source>
      <vertices id="floor-v"><input semantic="POSITION" source="#floor-p"/></vertices>
      <triangles material="grey" count="2"><input semantic="VERTEX" source="#floor-v" offset="0"/><p>0 1 2 0 2 3</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="s">
    <node id="Area"><matrix>0.6 0 0 0 0 0.8 0 0 0 0 1 1 0 0 0 1</matrix><instance_light url="#lamp"/></node>
    <node id="panel"><instance_geometry url="#panel"><bind_material><technique_common>
      <instance_material symbol="glow" target="#glow"/></technique_common></bind_material></instance_geometry></node>
    <node id="floor"><instance_geometry url="#floor"><bind_material><technique_common>
      <instance_material symbol="grey" target="#grey"/></technique_common></bind_material></instance_geometry></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";

// A panel unlike its light is said once, on standard error, naming the file and the light's
// element and what is rendered; a panel that is its light's shape says nothing.
TEST_F(CliTest, APanelUnlikeItsLightIsNamedOnceWithItsFile) {
  std::ofstream(file("panel.dae")) << kPanelUnlikeItsLight;
  Outcome run = pathtracer("-t 1 -s 1 -m 2 -r 8 6 -f panel.png panel.dae");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string head = "warning: panel.dae: <light name=\"Lamp\">";
  const size_t at = run.err.find(head);
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(head, at + 1), std::string::npos) << "said once: " << run.err;
  const std::string line = run.err.substr(at, run.err.find('\n', at) - at);
  EXPECT_NE(line.find("differ in shape;"), std::string::npos) << line;
  EXPECT_NE(line.find("the light's rectangle with its radiance lights the scene"), std::string::npos)
      << line;
  std::string agreeing = kPanelUnlikeItsLight;
  agreeing.replace(agreeing.find("0.6 0 0 0 0 0.8"), 15, "0.8 0 0 0 0 0.6");
  std::ofstream(file("agreeing.dae")) << agreeing;
  Outcome quiet = pathtracer("-t 1 -s 1 -m 2 -r 8 6 -f agreeing.png agreeing.dae");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("<light"), std::string::npos) << quiet.err;
}

TEST_F(CliTest, TheCourseCommandLinesRunWithOptionsOnEitherSideOfTheScene) {
  std::ofstream(file("lit.dae")) << lit_quad_scene();
  // The course's own command lines (its README's and write-up's), with its scene paths replaced
  // by this scene, its samples cut and 2 threads for 8, so the test takes seconds. The course
  // parses them with getopt, which takes the options on either side of the scene.
  struct Line {
    std::string args;
    std::string size;  // what -r asked for, as the summary prints it
  };
  const Line lines[] = {
      {"-t 2 -s 4 -l 16 -m 6 -r 48 36 -f spheres.png lit.dae", "48x36"},
      {"-t 2 -s 4 -l 1 -m 5 -r 48 36 -f CBbunny.png lit.dae", "48x36"},
      {"-t 2 -s 4 -l 32 -m 6 -H -f CBbunny_H_64_32.png -r 48 36 lit.dae", "48x36"},
      {"-t 2 -s 64 -a 16 0.05 -l 1 -m 5 -r 48 36 -f bunny.png lit.dae", "48x36"},
      {"-t 2 -s 4 -l 4 -m 5 -b 0.23 -d 4.5 -f dof.png -r 48 36 lit.dae", "48x36"},
      {"-t 2 -s 4 -l 4 -m 5 -o 0 -r 48 36 -f only_m.png lit.dae", "48x36"},
      {"-t 1 -s 1 -r 16 12 lit.dae -f out.png", "16x12"},  // the issue's line: -r, then the scene
      {"lit.dae -r 16 12 -f after.png -s 1 -t 1", "16x12"},
      {"-r 16 12 lit.dae -H -f after_h.png", "16x12"},
      {"-p 2 3 4 5 lit.dae -r 16 12 -f cell.png", "16x12 (cell 2 3 4 5)"},
  };
  for (const Line& line : lines) {
    Outcome run = pathtracer(line.args);
    EXPECT_FALSE(run.crashed) << line.args;
    ASSERT_EQ(run.exit_code, 0) << line.args << "\n" << run.err;
    EXPECT_NE(run.out.find("render: " + line.size), std::string::npos) << line.args << "\n" << run.out;
  }
  // The flags mean the same wherever they stand: one seed, one image.
  const std::string flags[][2] = {
      {"-t 2 -s 8 -l 4 -m 3 -r 24 18 -f a.png lit.dae", "lit.dae -f b.png -m 3 -r 24 18 -l 4 -t 2 -s 8"},
      {"-H -s 8 -r 24 18 -f a.png lit.dae", "-s 8 lit.dae -r 24 18 -H -f b.png"},
      {"-a 4 0.1 -s 16 -r 24 18 -f a.png lit.dae", "-r 24 18 -s 16 lit.dae -a 4 0.1 -f b.png"},
  };
  for (const auto& pair : flags) {
    ASSERT_EQ(pathtracer(pair[0]).exit_code, 0) << pair[0];
    ASSERT_EQ(pathtracer(pair[1]).exit_code, 0) << pair[1];
    EXPECT_TRUE(same_pixels(pt::read_image(file("a.png")), pt::read_image(file("b.png"))))
        << pair[0] << " and " << pair[1] << " rendered different images";
  }
  // -o 0 keeps bounce -m alone: at -m 1 that is direct light, which -m 0 (emission only) lacks.
  ASSERT_EQ(pathtracer("-o 0 -m 1 -s 2 -r 24 18 -f a.png lit.dae").exit_code, 0);
  ASSERT_EQ(pathtracer("--bounce 1 -m 1 -s 2 -r 24 18 -f b.png lit.dae").exit_code, 0);
  EXPECT_TRUE(same_pixels(pt::read_image(file("a.png")), pt::read_image(file("b.png"))));
  EXPECT_GT(pt::read_image(file("a.png")).at(12, 9).x, 0.0f);
  EXPECT_EQ(pathtracer("-o -1 -f c.png lit.dae").exit_code, 2);
}

TEST_F(CliTest, CameraSettingsFileIsTheCoursesSavedView) {
  std::ofstream(file("lit.dae")) << lit_quad_scene();
  // The course renderer's file for the scene's own camera: at the origin looking down -Z,
  // 60 degrees across at the file's 2:1 (vFov = 2 atan(tan 30° / 2) = 32.204°).
  auto settings = [](const std::string& c2w, const std::string& lens) {
    return "60 32.2042 2 0.1 100\n0 0 0 0 0 -1\n0 0 1 0.1 100\n" + c2w + "\n800 400 1\n" + lens + "\n";
  };
  std::ofstream(file("same.txt")) << settings("1 0 0 0 1 0 0 0 1", "1 0");
  std::ofstream(file("old.txt")) << settings("1 0 0 0 1 0 0 0 1", "");  // before the lens was saved
  std::ofstream(file("behind.txt")) << settings("-1 0 0 0 1 0 0 0 -1", "1 0");  // turned round
  ASSERT_EQ(pathtracer("--file-camera -s 2 -r 24 12 -f file.png lit.dae").exit_code, 0);
  Outcome same = pathtracer("-c same.txt -s 2 -r 24 12 -f same.png lit.dae");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  ASSERT_EQ(pathtracer("-s 2 -r 24 12 lit.dae -c old.txt -f old.png").exit_code, 0);
  ASSERT_EQ(pathtracer("-s 2 -r 24 12 -c behind.txt -f behind.png lit.dae").exit_code, 0);
  const pt::Image file_camera = pt::read_image(file("file.png"));
  EXPECT_TRUE(same_pixels(file_camera, pt::read_image(file("same.png"))));
  EXPECT_TRUE(same_pixels(file_camera, pt::read_image(file("old.png"))));
  EXPECT_GT(file_camera.at(12, 6).x, 0.0f);
  EXPECT_EQ(pt::read_image(file("behind.png")).at(12, 6), glm::vec3(0.0f));  // it sees nothing

  std::ofstream(file("short.txt")) << "60 32 2 0.1 100\n0 0 0\n";
  std::ofstream(file("word.txt")) << settings("1 0 0 0 one 0 0 0 1", "1 0");
  const std::pair<std::string, std::string> bad[] = {
      {"short.txt", "target.x"}, {"word.txt", "c2w[1][1]"}, {"absent.txt", "absent.txt"}};
  for (const auto& [name, mention] : bad) {
    Outcome run = pathtracer("-c " + name + " -f bad.png lit.dae");
    EXPECT_EQ(run.exit_code, 1) << name << "\n" << run.err;
    EXPECT_NE(run.err.find(mention), std::string::npos) << name << ": " << run.err;
    EXPECT_NE(run.err.find(name), std::string::npos) << name << ": " << run.err;
  }
  EXPECT_FALSE(fs::exists(file("bad.png")));
}
