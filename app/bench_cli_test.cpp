// The bench command line, run as a user runs it: one subcommand per measurement; a missing or
// unknown command, or an option a command does not have, is named with exit code 2.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grader/process/child_process.h"
#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"

namespace fs = std::filesystem;

namespace {

pt::ChildResult bench(std::vector<std::string> args) {
  args.insert(args.begin(), PT_BENCH);
  return pt::run_child(args, 120.0, {}, 1 << 22, pt::ChildStreams::separate);
}

std::string project_scene(const char* name) {
  return (fs::path(pt::test::source_dir()) / "scenes" / name).string();
}

TEST(BenchCli, HelpNamesEveryCommand) {
  const pt::ChildResult run = bench({"--help"});
  EXPECT_EQ(run.exit_code, 0) << run.errors;
  for (const char* command : {"rays", "render", "convergence", "agreement", "layers"})
    EXPECT_NE(run.output.find(command), std::string::npos) << command << " missing from:\n" << run.output;
}

TEST(BenchCli, EachCommandHasItsOwnHelp) {
  const std::pair<const char*, const char*> cases[] = {
      {"rays", "--embree"}, {"render", "--repeat"}, {"convergence", "--budgets"},
      {"agreement", "--hemisphere-samples"}, {"layers", "--seed"}};
  for (const auto& [command, option] : cases) {
    const pt::ChildResult run = bench({command, "--help"});
    EXPECT_EQ(run.exit_code, 0) << command << ": " << run.errors;
    EXPECT_NE(run.output.find(option), std::string::npos) << command << " --help:\n" << run.output;
  }
}

TEST(BenchCli, AMissingOrUnknownCommandIsNamed) {
  struct Case {
    std::vector<std::string> args;
    std::string must_mention;
  };
  const Case cases[] = {
      {{}, "say which command"},
      {{"speed"}, "'speed' is not a command"},
      // The forms before the subcommands: a scene first, or a study as a flag.
      {{project_scene("cornell_spheres.dae")}, "is not a command"},
      {{"--render"}, "'--render' is not a command"},
      {{"--convergence", project_scene("cornell_spheres.dae")}, "'--convergence' is not a command"},
  };
  for (const Case& c : cases) {
    const pt::ChildResult run = bench(c.args);
    const std::string what = c.args.empty() ? "(no arguments)" : c.args.front();
    EXPECT_EQ(run.exit_code, 2) << what << ": " << run.describe() << "\n" << run.errors;
    EXPECT_NE(run.errors.find(c.must_mention), std::string::npos) << what << ":\n" << run.errors;
    EXPECT_NE(run.errors.find("rays, render, convergence, agreement, layers"), std::string::npos)
        << what << ":\n" << run.errors;
    EXPECT_TRUE(run.output.empty()) << what << " printed on stdout:\n" << run.output;
  }
}

TEST(BenchCli, AnOptionTheCommandDoesNotHaveIsNamed) {
  const std::string scene = project_scene("cornell_spheres.dae");
  struct Case {
    std::vector<std::string> args;
    std::string must_mention;
  };
  const Case cases[] = {
      {{"rays", scene, "--budgets", "1,2"}, "--budgets"},      // convergence's, not rays'
      {{"render", "--wide"}, "--wide"},                        // rays', not render's
      {{"convergence", scene, "--rounds", "3"}, "--rounds"},   // rays', not convergence's
      {{"agreement", scene, "--repeat", "2"}, "--repeat"},     // render's, not agreement's
      {{"rays", scene, "--bvh", "octree"}, "--bvh"},
      {{"rays", scene, "--rounds", "0"}, "--rounds"},
      {{"agreement", scene, "-r", "0", "10"}, "-r"},
      {{"convergence"}, "scene"},
      {{"agreement"}, "scenes"},
  };
  for (const Case& c : cases) {
    const pt::ChildResult run = bench(c.args);
    std::string what;
    for (const std::string& a : c.args) what += a + " ";
    EXPECT_EQ(run.exit_code, 2) << what << ": " << run.describe() << "\n" << run.errors;
    EXPECT_NE(run.errors.find(c.must_mention), std::string::npos) << what << ":\n" << run.errors;
    EXPECT_TRUE(run.output.empty()) << what << " printed on stdout:\n" << run.output;
  }
}

TEST(BenchCli, AMissingSceneIsAnErrorOfTheFile) {
  const pt::ChildResult run = bench({"rays", "no_such_scene.dae", "--threads", "1"});
  EXPECT_EQ(run.exit_code, 1) << run.describe() << "\n" << run.errors;
  EXPECT_NE(run.errors.find("no_such_scene.dae"), std::string::npos) << run.errors;
}

TEST(BenchCli, RaysTimesTheProjectScene) {
  pt::test::TempFolder dir("pt-bench-cli");
  const std::string prefix = (dir.path() / "spheres").string();
  const pt::ChildResult run =
      bench({"rays", project_scene("cornell_spheres.dae"), "-r", "32", "--rounds", "1",
             "--min-seconds", "0", "--threads", "1", "--write-rays", prefix});
  ASSERT_EQ(run.exit_code, 0) << run.describe() << "\n" << run.errors;
  const auto out = nlohmann::json::parse(run.output, nullptr, false);
  ASSERT_TRUE(out.is_object()) << run.output;
  EXPECT_EQ(out["ray_counts"]["primary"], 32 * 24);
  EXPECT_GT(out["sah"]["mrays_per_s"]["primary"]["1"].get<double>(), 0.0) << run.output;
  // The sets it wrote read back as the same rays, with answers its own tree agrees with.
  const pt::ChildResult again =
      bench({"rays", project_scene("cornell_spheres.dae"), "--rays", prefix, "--rounds", "1",
             "--min-seconds", "0", "--threads", "1"});
  ASSERT_EQ(again.exit_code, 0) << again.describe() << "\n" << again.errors;
  const auto reread = nlohmann::json::parse(again.output, nullptr, false);
  ASSERT_TRUE(reread.is_object()) << again.output;
  EXPECT_EQ(reread["ray_counts"], out["ray_counts"]);
}

// A scene that is not there is named, as an error of the input (exit 1), and a resolution out of
// range is refused by the command line (exit 2).
TEST(BenchCli, LayersNamesAMissingSceneAndRefusesAnEmptyImage) {
#ifndef PT_HAVE_FAST_LIGHTS
  GTEST_SKIP() << "this build has no fast layer: bench layers compares nothing and exits 2";
#else
  const pt::ChildResult missing = bench({"layers", "no_such_scene.dae", "--threads", "1"});
  EXPECT_EQ(missing.exit_code, 1) << missing.describe() << "\n" << missing.errors;
  EXPECT_NE(missing.errors.find("no_such_scene.dae"), std::string::npos) << missing.errors;
  const pt::ChildResult empty =
      bench({"layers", project_scene("cornell_spheres.dae"), "-r", "0", "48"});
  EXPECT_EQ(empty.exit_code, 2) << empty.describe() << "\n" << empty.errors;
  EXPECT_NE(empty.errors.find("--resolution"), std::string::npos) << empty.errors;
#endif
}

// The whole renderer, linked as the instructor's build links it (bench and pathtracer whole,
// under PT_LTO), renders the course's scenes to the same bits whether the fast layer or the
// framework's definitions answer its light samples and shadow rays.
TEST(BenchCli, LayersRenderTheCourseScenesToTheSameBits) {
#ifndef PT_HAVE_FAST_LIGHTS
  GTEST_SKIP() << "this build has no fast layer (app/fast) to hold to the framework's bits";
#else
  std::vector<std::string> args = {"layers", "--threads", "2"};
  const fs::path shared = pt::test::shared_scenes_dir();
  if (fs::is_directory(shared))
    for (const auto& entry : fs::recursive_directory_iterator(shared))
      if (entry.path().extension() == ".dae") args.push_back(entry.path().string());
  if (args.size() == 3)
    GTEST_SKIP() << "the course's scenes are not at " << shared.string()
                 << " (../shared/scenes/cs184 beside the project)";
  const size_t scenes = args.size() - 3;
  const pt::ChildResult run = bench(args);
  EXPECT_EQ(run.exit_code, 0) << run.describe() << "\n" << run.output << run.errors;
  const std::string all = std::to_string(4 * scenes);
  EXPECT_NE(run.output.find(all + " of " + all + " renders the same"), std::string::npos)
      << run.output;
#endif
}

}  // namespace
