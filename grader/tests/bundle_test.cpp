// The Gradescope bundle never skips a check: without the course's scenes and ray sets beside the
// project there is no bundle, and the refusal names the folder to fill.
#include "grader/bundle.h"

#include <unistd.h>

#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

TEST(GraderBundle, NoBundleWithoutTheCoursesScenes) {
  const fs::path root = fs::temp_directory_path() / ("pt-bundle-test-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "project");
  fs::create_directories(root / "shared" / "rays");
  try {
    make_gradescope_bundle((root / "project").string(), (root / "out.zip").string());
    ADD_FAILURE() << "a bundle was made without the course's scenes";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("shared/scenes/cs184 is not there"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(root / "out.zip"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace pt::grader
