// The page's own pixel work: a zoomed crop is the region's pixels, each repeated as a square
// block (no smoothing that would hide noise), regions are checked, and the difference of two
// linear renders is their values subtracted, encoded as the pathtracer encodes a PNG.
#include "website/src/page_images.h"

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

#include "website/src/figure_html.h"
#include "framework/image/image.h"
#include "website/tests/test_folder.h"

namespace fs = std::filesystem;
using pt::web::PixelSize;
using pt::web::Region;
using pt::web::testing::TestFolder;

namespace {

/// A w × h PNG whose pixel (x, y) is (x, y, x + y) in 8-bit values.
fs::path numbered_png(const fs::path& file, int w, int h) {
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf buf(spec);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float px[3] = {x / 255.0f, y / 255.0f, (x + y) / 255.0f};
      buf.setpixel(x, y, px);
    }
  }
  EXPECT_TRUE(buf.write(file.string(), OIIO::TypeDesc::UINT8));
  return file;
}

}  // namespace

TEST(WebsitePageImages, ZoomedCropRepeatsEachPixelOfTheRegionAsABlock) {
  TestFolder dir;
  fs::path from = numbered_png(dir.path() / "render.png", 40, 20);
  // x from 10 to 20, y from 5 to 15: 10 × 10 pixels, enlarged 4 times to fit 40 wide.
  PixelSize size = pt::web::write_zoomed_crop(from, Region{0.25, 0.25, 0.25, 0.5}, 43,
                                              dir.path() / "crop.png");
  EXPECT_EQ(size.width, 40);
  EXPECT_EQ(size.height, 40);
  OIIO::ImageBuf crop((dir.path() / "crop.png").string());
  ASSERT_TRUE(crop.read(0, 0, true, OIIO::TypeDesc::UINT8));
  ASSERT_EQ(crop.spec().width, 40);
  ASSERT_EQ(crop.spec().height, 40);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      float px[3];
      crop.getpixel(x, y, px);
      int sx = 10 + x / 4, sy = 5 + y / 4;
      ASSERT_EQ(int(px[0] * 255 + 0.5f), sx) << x << "," << y;
      ASSERT_EQ(int(px[1] * 255 + 0.5f), sy) << x << "," << y;
      ASSERT_EQ(int(px[2] * 255 + 0.5f), sx + sy) << x << "," << y;
    }
  }
}

TEST(WebsitePageImages, RegionsAreFractionsInsideTheImage) {
  Region r = pt::web::parse_region("0.5 0.72 0.25 0.25");
  EXPECT_DOUBLE_EQ(r.x, 0.5);
  EXPECT_DOUBLE_EQ(r.h, 0.25);
  auto p = pt::web::region_pixels(r, {320, 240});
  EXPECT_EQ(p.x, 160);
  EXPECT_EQ(p.y, 172);
  EXPECT_EQ(p.width, 80);
  EXPECT_EQ(p.height, 60);
  EXPECT_THROW(pt::web::parse_region("0.5 0.5 0.6 0.1"), std::invalid_argument);  // past the edge
  EXPECT_THROW(pt::web::parse_region("0.5 0.5 0.1"), std::invalid_argument);
  EXPECT_THROW(pt::web::parse_region("0.1 0.1 0 0.1"), std::invalid_argument);
  EXPECT_THROW(pt::web::parse_region("0.1 0.1 0.1 0.1 5"), std::invalid_argument);
  EXPECT_THROW(pt::web::parse_region("nan 0.1 0.1 0.1"), std::invalid_argument);
}

TEST(WebsitePageImages, DifferenceIsOfLinearValuesAndNeverNegative) {
  TestFolder dir;
  pt::Image a(3, 1), b(3, 1);
  a.at(0, 0) = {0.5f, 0.2f, 1.5f};
  b.at(0, 0) = {0.25f, 0.3f, 0.5f};
  a.at(2, 0) = b.at(2, 0) = glm::vec3(0.7f);
  pt::write_image((dir.path() / "a.exr").string(), a);
  pt::write_image((dir.path() / "b.exr").string(), b);
  pt::web::write_difference(dir.path() / "a.exr", dir.path() / "b.exr", dir.path() / "d.png");
  pt::Image d = pt::read_image((dir.path() / "d.png").string());
  ASSERT_EQ(d.width(), 3);
  EXPECT_NEAR(d.at(0, 0).x, 0.25f, 0.005f);  // 0.5 - 0.25, through 8-bit sRGB
  EXPECT_EQ(d.at(0, 0).y, 0.0f);             // 0.2 - 0.3 < 0: black, not wrapped round
  EXPECT_NEAR(d.at(0, 0).z, 1.0f, 1e-6f);    // 1.0, clamped as the pathtracer clamps
  EXPECT_EQ(d.at(2, 0), glm::vec3(0.0f));

  pt::write_image((dir.path() / "small.exr").string(), pt::Image(2, 1));
  try {
    pt::web::write_difference(dir.path() / "a.exr", dir.path() / "small.exr", dir.path() / "e.png");
    FAIL() << "renders of different sizes cannot be subtracted";
  } catch (const pt::web::PageImageError& e) {
    EXPECT_NE(std::string(e.what()).find("the same size"), std::string::npos) << e.what();
  }
}

TEST(WebsitePageImages, NumbersReadAsAPersonWritesThem) {
  EXPECT_EQ(pt::web::thousands(1234567), "1,234,567");
  EXPECT_EQ(pt::web::thousands(999), "999");
  EXPECT_EQ(pt::web::seconds_text(0.421), "0.42 s");
  EXPECT_EQ(pt::web::seconds_text(12.34), "12.3 s");
  EXPECT_EQ(pt::web::seconds_text(125), "2 min 05 s");
}

TEST(WebsitePageImages, ImageTagCarriesItsSizeAndTheZoomedRegion) {
  pt::web::PageImage img{"renders/a.png", {320, 240}, "a \"quoted\" caption", std::nullopt};
  std::string plain = pt::web::image_html(img);
  EXPECT_NE(plain.find("width=\"320\" height=\"240\""), std::string::npos) << plain;
  EXPECT_NE(plain.find("&quot;quoted&quot;"), std::string::npos) << plain;
  img.marked = pt::web::PixelRect{160, 180, 80, 60};
  std::string marked = pt::web::image_html(img);
  EXPECT_NE(marked.find("left:50%;top:75%;width:25%;height:25%"), std::string::npos) << marked;
}
