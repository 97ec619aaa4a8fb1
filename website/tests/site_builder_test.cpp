// `website build` on small write-ups: images and renders land in the folder, renders come from
// the cache when nothing changed, and every mistake is reported at its line of the Markdown.
#include "website/src/site_builder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "framework/text/text_file.h"
#include "website/tests/test_folder.h"

namespace fs = std::filesystem;
using pt::web::BuildOptions;
using pt::web::BuildReport;
using pt::web::Problem;
using pt::web::testing::TestFolder;

namespace {

std::string all(const std::vector<Problem>& problems) {
  std::string s;
  for (const Problem& p : problems) s += p.to_string() + "\n";
  return s;
}

std::string read(const fs::path& p) { return pt::read_text_file(p); }

/// A write-up folder with a scene, the fake pathtracer, and a log of its runs.
class WebsiteBuild : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_.write("scene.dae", "<COLLADA/>\n");
    setenv("FAKE_PATHTRACER_LOG", (dir_.path() / "runs.log").c_str(), 1);
  }
  void TearDown() override { unsetenv("FAKE_PATHTRACER_LOG"); }

  BuildReport build(const std::string& markdown) {
    dir_.write("src/writeup.md", markdown);
    if (fs::exists(dir_.path() / "src" / "scene.dae") == false) {
      fs::copy_file(dir_.path() / "scene.dae", dir_.path() / "src" / "scene.dae");
    }
    BuildOptions o;
    o.source = dir_.path() / "src" / "writeup.md";
    o.out_dir = dir_.path() / "site";
    o.web_dir = PT_WEBSITE_DIR;
    o.pathtracer = PT_FAKE_PATHTRACER;
    o.cache_dir = dir_.path() / "cache";
    return pt::web::build_site(o);
  }

  int runs() {
    std::ifstream in(dir_.path() / "runs.log");
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  }

  fs::path md() const { return dir_.path() / "src" / "writeup.md"; }

  /// Exactly one problem, at line `line` of the Markdown, whose message contains `words`.
  void expect_one(const BuildReport& r, int line, const std::string& words) {
    ASSERT_EQ(r.problems.size(), 1u) << all(r.problems);
    EXPECT_EQ(r.problems[0].file, md());
    EXPECT_EQ(r.problems[0].line, line) << r.problems[0].to_string();
    EXPECT_NE(r.problems[0].message.find(words), std::string::npos) << r.problems[0].message;
  }

  TestFolder dir_;
};

}  // namespace

TEST_F(WebsiteBuild, WritesPageImagesRendersAndMath) {
  dir_.image("src/images/photo.png");
  auto r = build("# Title\n\nSee $s = 1, l = 4$.\n\n![photo](images/photo.png)\n\n"
                 "```render scene=scene.dae flags=\"-s 4 -r 20 10\" caption=\"four\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  std::string html = read(dir_.path() / "site" / "index.html");
  EXPECT_NE(html.find("<img src=\"images/photo.png\""), std::string::npos);
  EXPECT_NE(html.find("class=\"katex\""), std::string::npos);
  EXPECT_NE(html.find("katex/katex.min.css"), std::string::npos);
  EXPECT_NE(html.find("pathtracer -s 4 -r 20 10 scene.dae"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_.path() / "site" / "images" / "photo.png"));
  EXPECT_EQ(r.renders_made, 1);
  EXPECT_TRUE(pt::web::check_folder(dir_.path() / "site").empty());
}

TEST_F(WebsiteBuild, SecondBuildTakesRendersFromTheCache) {
  std::string grid = "```grid flags=\"-r 8 8\"\nscene=scene.dae flags=\"-s 1\"\n"
                     "scene=scene.dae flags=\"-s 4\"\n```\n";
  ASSERT_TRUE(build(grid).problems.empty());
  EXPECT_EQ(runs(), 2);
  auto again = build(grid);
  ASSERT_TRUE(again.problems.empty());
  EXPECT_EQ(runs(), 2) << "nothing changed, so nothing is rendered again";
  EXPECT_EQ(again.renders_cached, 2);
  // New flags, or a changed scene file, mean a new render.
  ASSERT_TRUE(build(grid + "```render scene=scene.dae flags=\"-s 16\"\n```\n").problems.empty());
  EXPECT_EQ(runs(), 3);
  dir_.write("src/scene.dae", "<COLLADA version=\"1.4.1\"/>\n");
  ASSERT_TRUE(build(grid).problems.empty());
  EXPECT_EQ(runs(), 5);
}

TEST_F(WebsiteBuild, GridCellFlagsReplaceTheSharedOnes) {
  auto r = build("```grid flags=\"-s 4 -r 160 120\"\nscene=scene.dae flags=\"-r 8 6\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  EXPECT_NE(read(dir_.path() / "site" / "index.html").find("pathtracer -s 4 -r 8 6 scene.dae"),
            std::string::npos);
}

TEST_F(WebsiteBuild, AbsoluteImagePathIsReportedAtItsLine) {
  fs::path img = dir_.image("src/photo.png");
  expect_one(build("# T\n\ntext\n![photo](" + img.string() + ")\n"), 4, "absolute path");
}

TEST_F(WebsiteBuild, WrongCapitalisationIsReportedAtItsLine) {
  dir_.image("src/Photo.png");
  expect_one(build("# T\n\n![photo](photo.png)\n"), 3, "wrong capitalisation");
}

TEST_F(WebsiteBuild, MissingImageIsReportedAtItsLine) {
  expect_one(build("# T\n\n$x$ and $$y$$\n\n<img src=\"gone.png\">\n"), 5, "missing");
}

TEST_F(WebsiteBuild, JpegNamedPngIsReportedAtItsLine) {
  dir_.image("src/photo.png", ".jpg");
  expect_one(build("# T\n\n\n![photo](photo.png)\n"), 4, "really a JPEG");
}

TEST_F(WebsiteBuild, UnreadableImageIsReportedAtItsLine) {
  fs::path img = dir_.image("src/photo.png");
  fs::permissions(img, fs::perms(0600));
  expect_one(build("# T\n\n![photo](photo.png)\n"), 3, "not readable by others");
}

TEST_F(WebsiteBuild, LinesCountFromTheSourceAfterMultiLineMath) {
  expect_one(build("# T\n\n$$\na\n\\\\\nb\n$$\n\n![p](nowhere.png)\n"), 9, "missing");
}

TEST_F(WebsiteBuild, FailedRenderIsReportedWithThePathtracersMessage) {
  auto r = build("# T\n\n```render scene=scene.dae flags=\"--fail\"\n```\n");
  expect_one(r, 3, "scene has no camera");
}

TEST_F(WebsiteBuild, MissingSceneAndBadAttributeAreReportedAtTheirLines) {
  auto r = build("```render scene=nowhere.dae\n```\n\n```render scene=scene.dae size=3\n```\n");
  ASSERT_EQ(r.problems.size(), 2u) << all(r.problems);
  EXPECT_EQ(r.problems[0].line, 1);
  EXPECT_NE(r.problems[0].message.find("not found"), std::string::npos);
  EXPECT_EQ(r.problems[1].line, 4);
  EXPECT_NE(r.problems[1].message.find("unknown attribute 'size'"), std::string::npos);
}

TEST_F(WebsiteBuild, BadGridCellIsReportedAtItsOwnLine) {
  auto r = build("# T\n```grid\nscene=scene.dae\nscene=scene.dae flags=\"-s 4\n```\n");
  expect_one(r, 4, "unclosed");
}

TEST_F(WebsiteBuild, MathKatexCannotReadIsReportedAtItsLine) {
  expect_one(build("# T\n\nfine $x$\nbroken $\\frac{1$\n"), 4, "math");
}

TEST_F(WebsiteBuild, ExtrasShowTheSampleRateImage) {
  auto r = build("```render scene=scene.dae flags=\"-a 8 0.05\" extras=yes\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  EXPECT_NE(read(dir_.path() / "site" / "index.html").find("render_rate.png"), std::string::npos);
}
