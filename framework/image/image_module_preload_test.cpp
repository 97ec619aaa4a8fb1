// Not needed for the assignment.
// Opening the image module beside a render: it never reports a failure itself, the image write
// that follows still does (naming the image), and a preloaded module writes the image.
#include "framework/image/image_module_preload.h"

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "framework/image/image.h"

namespace fs = std::filesystem;

namespace {

/// Each test in a fresh folder under the system temp directory, with the module looked for
/// where the build put it again at the end.
class PreloadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pt_preload_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    unsetenv("PT_IMAGE_MODULE_DIR");
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

TEST_F(PreloadTest, AModuleThatCannotBeOpenedIsReportedByTheWriteNotThePreload) {
  ASSERT_EQ(setenv("PT_IMAGE_MODULE_DIR", file("nowhere").c_str(), 1), 0);
  const std::string out = file("lost.png");
  {
    pt::ImageModulePreload preload(out);
    preload.wait();
    preload.wait();  // idempotent; the destructor waits once more
  }
  try {
    pt::write_image(out, pt::Image(4, 3, glm::vec3(0.5f)));
    FAIL() << "write_image wrote with no module to write through";
  } catch (const pt::ImageError& e) {
    EXPECT_EQ(e.path(), out);
    EXPECT_NE(std::string(e.what()).find("pt_image_oiio.so"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(PreloadTest, APreloadedModuleWritesTheImage) {
  const std::string out = file("written.png");
  pt::ImageModulePreload preload(out);
  preload.wait();
  pt::write_image(out, pt::Image(4, 3, glm::vec3(0.5f)));
  EXPECT_TRUE(fs::exists(out));
  EXPECT_GT(fs::file_size(out), 0u);
}

}  // namespace
