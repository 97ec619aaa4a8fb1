// Not needed for the assignment.
// Image files: sRGB PNG and float EXR round trips, extra EXR channels, and clear errors.
#include "framework/image/image.h"

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "framework/image/estimate_exr.h"
#include "framework/sampling/rng.h"

namespace fs = std::filesystem;

namespace {

/// A fresh folder under the system temp directory, removed with everything in it at the end.
class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("pt_image_test_" + std::to_string(getpid()) +
             "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

pt::Image random_image(int width, int height, float scale, uint64_t seed) {
  pt::Image image(width, height);
  pt::Rng rng(seed);
  for (glm::vec3& p : image.pixels()) p = scale * glm::vec3(rng.next_float(), rng.next_float(), rng.next_float());
  return image;
}

}  // namespace

TEST(FrameworkImage, SrgbCurveKnownValues) {
  EXPECT_FLOAT_EQ(pt::srgb_encode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(pt::srgb_encode(1.0f), 1.0f);
  EXPECT_NEAR(pt::srgb_encode(0.18f), 0.46135f, 1e-4f);  // middle grey
  EXPECT_NEAR(pt::srgb_encode(0.002f), 0.002f * 12.92f, 1e-7f);  // linear toe
  EXPECT_FLOAT_EQ(pt::srgb_encode(7.0f), 1.0f);  // clamped
  EXPECT_FLOAT_EQ(pt::srgb_encode(-1.0f), 0.0f);
  EXPECT_FLOAT_EQ(pt::srgb_encode(std::nanf("")), 0.0f);
  for (float v = 0.0f; v <= 1.0f; v += 1.0f / 97.0f)
    EXPECT_NEAR(pt::srgb_decode(pt::srgb_encode(v)), v, 1e-5f) << v;
}

TEST(FrameworkImage, PngRoundTripWithinOneStep) {
  TempDir dir;
  pt::Image image = random_image(37, 23, 1.0f, 1);  // odd sizes catch row-stride mistakes
  image.at(0, 0) = glm::vec3(5.0f, -1.0f, 0.5f);   // out of range: clamped
  std::string path = dir.file("round.png");
  pt::write_image(path, image);
  pt::Image back = pt::read_image(path);
  ASSERT_EQ(back.width(), 37);
  ASSERT_EQ(back.height(), 23);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x)
      for (int c = 0; c < 3; ++c) {
        float expected = pt::srgb_encode(image.at(x, y)[c]);
        float got = pt::srgb_encode(back.at(x, y)[c]);
        // Rounding to 8 bits moves an encoded value by at most half a step.
        ASSERT_LE(std::fabs(got - expected), 0.5f / 255.0f + 1e-5f) << x << "," << y << "," << c;
      }
}

TEST(FrameworkImage, PngStoresSrgbNotLinear) {
  TempDir dir;
  std::string path = dir.file("grey.png");
  pt::write_image(path, pt::Image(2, 2, glm::vec3(0.18f)));
  pt::ChannelImage raw = pt::read_channels(path);  // the file's code values, undecoded
  ASSERT_EQ(raw.channels.size(), 3u);
  EXPECT_NEAR(raw.at(1, 1, 0) * 255.0f, 118.0f, 0.01f);  // round(255 * 0.46135)
}

TEST(FrameworkImage, ExrRoundTripIsExact) {
  TempDir dir;
  pt::Image image = random_image(19, 11, 1000.0f, 2);
  image.at(3, 4) = glm::vec3(1e-30f, 3.4e38f, 0.1f);  // beyond half's range and precision
  std::string path = dir.file("round.EXR");  // extensions are case-insensitive
  pt::write_image(path, image);
  pt::Image back = pt::read_image(path);
  ASSERT_EQ(back.width(), 19);
  ASSERT_EQ(back.height(), 11);
  for (size_t i = 0; i < image.pixels().size(); ++i)
    ASSERT_EQ(back.pixels()[i], image.pixels()[i]) << "pixel " << i;
}

TEST(FrameworkImage, ExrExtraChannelsRoundTrip) {
  TempDir dir;
  pt::ChannelImage image(5, 3, {"R", "G", "B", "varR", "varG", "varB", "n"});
  pt::Rng rng(3);
  for (float& v : image.values) v = rng.next_float() * 17.0f;
  std::string path = dir.file("channels.exr");
  pt::write_exr(path, image);
  pt::ChannelImage back = pt::read_channels(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  ASSERT_EQ(back.channels.size(), image.channels.size());
  // EXR keeps its channels sorted by name, so they come back by name, not in the order written.
  for (int c = 0; c < int(image.channels.size()); ++c) {
    int b = back.channel_index(image.channels[size_t(c)]);
    ASSERT_GE(b, 0) << "channel " << image.channels[size_t(c)] << " lost";
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) ASSERT_EQ(back.at(x, y, b), image.at(x, y, c));
  }
}

TEST(FrameworkImage, EstimateExrRoundTrip) {
  TempDir dir;
  pt::RenderEstimate e;
  e.width = 4, e.height = 3;
  pt::Rng rng(4);
  for (int i = 0; i < 12; ++i) {
    e.mean.emplace_back(rng.next_float(), rng.next_float(), 2.0f * rng.next_float());
    e.variance.emplace_back(rng.next_float(), 0.0f, 1e-9f * rng.next_float());
    e.count.push_back(float(1 + i * 7));
  }
  std::string path = dir.file("estimate.exr");
  pt::write_estimate_exr(path, e);
  pt::RenderEstimate back = pt::read_estimate_exr(path);
  EXPECT_EQ(back.width, 4);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.mean, e.mean);
  EXPECT_EQ(back.variance, e.variance);
  EXPECT_EQ(back.count, e.count);
}

TEST(FrameworkImage, EstimateExrNamesMissingChannel) {
  TempDir dir;
  std::string path = dir.file("plain.exr");
  pt::write_image(path, pt::Image(2, 2));
  try {
    pt::read_estimate_exr(path);
    FAIL() << "an RGB-only EXR was read as an estimate";
  } catch (const pt::ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("varR"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(FrameworkImage, UnknownExtensionIsRefusedByName) {
  TempDir dir;
  std::string path = dir.file("out.jpg");
  try {
    pt::write_image(path, pt::Image(2, 2));
    FAIL() << "wrote a .jpg";
  } catch (const pt::ImageError& e) {
    std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(".jpg"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_THROW(pt::write_image(dir.file("noextension"), pt::Image(2, 2)), pt::ImageError);
}

TEST(FrameworkImage, UnwritablePathIsReported) {
  TempDir dir;
  std::string path = dir.file("no/such/folder/out.png");
  try {
    pt::write_image(path, pt::Image(2, 2));
    FAIL() << "wrote into a folder that does not exist";
  } catch (const pt::ImageError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  // A folder where the file should be: OpenImageIO's own open fails, and says so.
  fs::create_directories(dir.file("taken.exr"));
  EXPECT_THROW(pt::write_image(dir.file("taken.exr"), pt::Image(2, 2)), pt::ImageError);
}

TEST(FrameworkImage, EmptyImageAndMissingFileAreErrors) {
  TempDir dir;
  EXPECT_THROW(pt::write_image(dir.file("empty.png"), pt::Image()), pt::ImageError);
  EXPECT_THROW(pt::read_image(dir.file("absent.png")), pt::ImageError);
}
