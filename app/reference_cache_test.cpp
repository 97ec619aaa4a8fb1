// The convergence study's reference is cached: reused while the scene's bytes and the image
// settings are the same, made again when either changes, when asked, or when the cache is broken.
#include "app/reference_cache.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

/// A fresh folder in the temp directory with a scene file in it, removed when the test ends.
class BenchReferenceCache : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = folder_.write("scene.dae", "<COLLADA>a scene</COLLADA>\n");
    settings_.width = 6;
    settings_.height = 4;
    settings_.samples_per_pixel = 64;
    settings_.seed = 99;
  }

  /// Stands in for a render: a flat image whose value says which call made it.
  Reference get(const RenderSettings& s, bool fresh = false) {
    ReferenceRenderer render = [this](const RenderSettings& r) {
      ++renders_;
      ReferenceRender out;
      out.estimate.width = r.width;
      out.estimate.height = r.height;
      const size_t n = size_t(r.width) * size_t(r.height);
      out.estimate.mean.assign(n, glm::vec3(float(renders_)));
      out.estimate.variance.assign(n, glm::vec3(0.04f));
      out.estimate.count.assign(n, 4.0f);
      out.seconds = 1.5;
      return out;
    };
    std::ostringstream log;
    return load_or_make_reference(scene_.string(), s, dir_ / "cache", render, fresh, log);
  }

  test::TempFolder folder_{"pt-reference-cache"};
  const fs::path& dir_ = folder_.path();
  fs::path scene_;
  RenderSettings settings_;
  int renders_ = 0;
};

TEST_F(BenchReferenceCache, ReusedWhenTheKeyMatches) {
  Reference first = get(settings_);
  EXPECT_FALSE(first.reused);
  EXPECT_EQ(renders_, 1);
  EXPECT_TRUE(fs::exists(first.exr));
  EXPECT_TRUE(fs::exists(first.manifest));
  Reference again = get(settings_);
  EXPECT_TRUE(again.reused);
  EXPECT_EQ(renders_, 1) << "a matching cached reference must not be rendered again";
  EXPECT_EQ(again.key, first.key);
  EXPECT_EQ(again.image.at(5, 3), glm::vec3(1.0f)) << "the cached image is the first render's";
  EXPECT_DOUBLE_EQ(again.seconds, 1.5) << "the manifest keeps how long the reference took";
  // The thread count changes the time, not the image: the same reference serves.
  RenderSettings threads = settings_;
  threads.threads = 1;
  EXPECT_TRUE(get(threads).reused);
}

TEST_F(BenchReferenceCache, RemadeWhenTheSceneOrASettingChanges) {
  const std::string key = get(settings_).key;
  RenderSettings more = settings_;
  more.samples_per_pixel = 128;
  EXPECT_FALSE(get(more).reused);
  RenderSettings seed = settings_;
  seed.seed = 100;
  EXPECT_FALSE(get(seed).reused);
  RenderSettings depth = settings_;
  depth.max_depth = 7;
  EXPECT_FALSE(get(depth).reused);
  EXPECT_EQ(renders_, 4);
  std::ofstream(scene_, std::ios::app) << "<!-- one more byte -->\n";
  Reference edited = get(settings_);
  EXPECT_FALSE(edited.reused) << "an edited scene file must not reuse the old reference";
  EXPECT_NE(edited.key, key);
  EXPECT_EQ(renders_, 5);
}

TEST_F(BenchReferenceCache, RemadeWhenAskedOrWhenTheCacheIsBroken) {
  Reference first = get(settings_);
  EXPECT_FALSE(get(settings_, /*fresh=*/true).reused);
  EXPECT_EQ(renders_, 2);
  std::ofstream(first.manifest) << "{\"key\": \"0000000000000000\"}";
  EXPECT_FALSE(get(settings_).reused) << "a manifest with another key does not vouch for the image";
  std::ofstream(first.exr) << "not an EXR";
  EXPECT_FALSE(get(settings_).reused) << "an unreadable image is rendered again, not a crash";
  EXPECT_EQ(renders_, 4);
  EXPECT_TRUE(get(settings_).reused);
}

TEST_F(BenchReferenceCache, ItsOwnNoiseIsEstimatedFromItsVariance) {
  // Mean 1, variance of one sample 0.04, 4 samples: var/n/(ref^2 + eps) per channel.
  Reference ref = get(settings_);
  EXPECT_NEAR(ref.noise_rel_mse, 0.04 / 4.0 / 1.01, 1e-6);
}

TEST_F(BenchReferenceCache, UnreadableSceneIsNamed) {
  try {
    reference_key((dir_ / "missing.dae").string(), settings_);
    FAIL() << "a scene that cannot be read has no key";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.dae"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pt
