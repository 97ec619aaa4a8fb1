// `website build` on small write-ups: images and renders land in the folder, renders come from
// the cache when nothing changed, and every mistake is reported at its line of the Markdown.
#include "website/src/site_builder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "framework/image/image.h"
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

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
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

  BuildReport build(const std::string& markdown, bool quick = false, int time_limit = 0) {
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
    o.bench = PT_FAKE_PATHTRACER;  // it stands in for bench convergence too
    o.quick = quick;
    o.time_limit_seconds = time_limit;
    return pt::web::build_site(o);
  }

  int runs() {
    std::ifstream in(dir_.path() / "runs.log");
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  }

  fs::path md() const { return dir_.path() / "src" / "writeup.md"; }
  std::string page() const { return read(dir_.path() / "site" / "index.html"); }

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

TEST_F(WebsiteBuild, ImagesCarryTheirSizeAndThePageItsRenderTime) {
  auto r = build("```render scene=scene.dae flags=\"-r 20 10\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  EXPECT_NE(page().find("width=\"20\" height=\"10\""), std::string::npos);
  EXPECT_GT(r.render_seconds, 0.0);
  EXPECT_NE(page().find("class=\"render-time\""), std::string::npos);
  EXPECT_EQ(page().find("class=\"draft\""), std::string::npos);
}

TEST_F(WebsiteBuild, QuickBuildRendersAtHalfTheSizeAndSaysItIsADraft) {
  auto r = build("```render scene=scene.dae flags=\"-r 20 10 -s 64\"\n```\n", true);
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  EXPECT_NE(page().find("pathtracer -r 10 5 -s 64 scene.dae"), std::string::npos);
  EXPECT_NE(page().find("width=\"10\" height=\"5\""), std::string::npos);
  EXPECT_NE(page().find("class=\"draft\""), std::string::npos);
}

TEST_F(WebsiteBuild, ZoomShowsTheRegionEnlargedUnderEachCellAndOutlinesIt) {
  auto r = build("```grid flags=\"-r 40 20\" zoom=\"0.5 0.5 0.25 0.5\"\nscene=scene.dae flags=\"-s 1\"\n"
                 "scene=scene.dae flags=\"-s 4\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  std::string html = page();
  EXPECT_EQ(count(html, "class=\"crop\""), 2);
  EXPECT_EQ(count(html, "class=\"zoom-box\" style=\"left:50%;top:50%;width:25%;height:50%\""), 2);
  // 10 × 10 pixels, four times over: as wide as the render.
  EXPECT_EQ(count(html, "class=\"crop\" width=\"40\" height=\"40\""), 2) << html;
  EXPECT_TRUE(pt::web::check_folder(dir_.path() / "site").empty());
}

TEST_F(WebsiteBuild, BadZoomIsReportedAtItsLine) {
  expect_one(build("# T\n```grid zoom=\"0.9 0 0.2 0.1\"\nscene=scene.dae\n```\n"), 2, "not inside");
}

TEST_F(WebsiteBuild, CompareIsASliderBetweenTwoRendersWithItsScript) {
  auto r = build("```compare flags=\"-r 30 20\" zoom=\"0 0 0.5 0.5\" caption=\"two\"\n"
                 "scene=scene.dae flags=\"-H\" caption=\"hemisphere\"\n"
                 "scene=scene.dae caption=\"lights\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  std::string html = page();
  EXPECT_EQ(count(html, "class=\"slider\""), 1);
  EXPECT_EQ(count(html, "class=\"slider-over\""), 1);
  EXPECT_EQ(count(html, "class=\"slider-under\""), 1);
  EXPECT_EQ(count(html, "type=\"range\""), 1);
  EXPECT_EQ(count(html, "class=\"crop\""), 2);
  EXPECT_NE(html.find("<script src=\"compare.js\" defer>"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_.path() / "site" / "compare.js"));
  EXPECT_NE(html.find("left: <code>pathtracer -r 30 20 -H scene.dae</code>"), std::string::npos);
  EXPECT_TRUE(pt::web::check_folder(dir_.path() / "site").empty());
}

TEST_F(WebsiteBuild, PageWithoutComparisonsHasNoScript) {
  ASSERT_TRUE(build("```render scene=scene.dae\n```\n").problems.empty());
  EXPECT_EQ(page().find("<script"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_.path() / "site" / "compare.js"));
}

TEST_F(WebsiteBuild, CompareNeedsTwoPicturesOfOneSize) {
  expect_one(build("# T\n```compare\nscene=scene.dae\n```\n"), 2, "exactly two lines");
  expect_one(build("```compare\nscene=scene.dae flags=\"-r 8 8\"\nscene=scene.dae flags=\"-r 8 6\"\n```\n"),
             3, "the same size");
}

TEST_F(WebsiteBuild, MinusShowsTheDifferenceOfTwoLinearRendersAndShares) {
  // The fake's picture is scaled by m / 5: 5/5 - 1/5 leaves 0.8 of it in red and green, and
  // the same blue (the other flags are the same) cancels.
  auto r = build("```grid flags=\"-r 8 4 -s 4\"\nscene=scene.dae flags=\"-m 1\"\n"
                 "scene=scene.dae flags=\"-m 5\" minus=\"-m 1\"\nscene=scene.dae flags=\"-m 5\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  EXPECT_EQ(runs(), 2) << "the plain cells take the PNG of the linear renders";
  fs::path diff;
  for (const auto& e : fs::directory_iterator(dir_.path() / "site" / "renders")) {
    if (e.path().string().find("-minus-") != std::string::npos) diff = e.path();
  }
  ASSERT_FALSE(diff.empty());
  pt::Image d = pt::read_image(diff.string());
  ASSERT_EQ(d.width(), 8);
  EXPECT_NEAR(d.at(7, 3).x, 0.8f, 0.01f);
  EXPECT_NEAR(d.at(7, 3).y, 0.8f, 0.01f);
  EXPECT_EQ(d.at(7, 3).z, 0.0f);
  EXPECT_NEAR(d.at(0, 0).x, 0.0f, 1e-6f);
  EXPECT_NE(page().find("pathtracer -r 8 4 -s 4 -m 5 scene.dae  minus  pathtracer -r 8 4 -s 4 -m 1 scene.dae"),
            std::string::npos);
}

TEST_F(WebsiteBuild, TimingTableComparesCameraRaysASecond) {
  auto r = build("```timing flags=\"-r 20 10\" versus=\"-r 4 4 --bvh none\" names=\"BVH|none\"\n"
                 "scene=scene.dae caption=\"the scene\"\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  std::string html = page();
  // 20·10·4 rays in 0.25 s against 4·4·4 in 25 s: 3200 against 2.56 rays a second.
  EXPECT_NE(html.find("3,200 rays/s"), std::string::npos) << html;
  EXPECT_NE(html.find("800 rays in 0.25 s"), std::string::npos) << html;
  EXPECT_NE(html.find("× 1,250"), std::string::npos) << html;
  EXPECT_NE(html.find("<th>BVH</th><th>none</th>"), std::string::npos);
}

TEST_F(WebsiteBuild, TimingNeedsTwoColumnNames) {
  expect_one(build("```timing names=\"one\"\nscene=scene.dae\n```\n"), 1, "two column names");
}

TEST_F(WebsiteBuild, PlotOfAMissingTableIsMeasuredOnceAndCached) {
  std::string md = "```plot scene=scene.dae flags=\"--budgets 1,4,16\" caption=\"error\"\n```\n";
  auto r = build(md);
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  std::string html = page();
  EXPECT_NE(html.find("<img src=\"plots/convergence-scene-seconds.svg\" width=\"640\""), std::string::npos)
      << html;
  EXPECT_NE(html.find("href=\"plots/convergence-scene.csv\""), std::string::npos);
  EXPECT_NE(html.find("bench convergence scene.dae --budgets 1,4,16"), std::string::npos);
  // bench's summary: the time each strategy needs to reach the target error.
  EXPECT_NE(html.find("class=\"time-to-target\""), std::string::npos);
  EXPECT_NE(html.find("≈ 16.0 s"), std::string::npos) << html;
  EXPECT_EQ(runs(), 1);
  ASSERT_TRUE(build(md).problems.empty());
  EXPECT_EQ(runs(), 1) << "the study is kept like a render";
  EXPECT_TRUE(pt::web::check_folder(dir_.path() / "site").empty());
}

TEST_F(WebsiteBuild, PlotPrefersTheStudentsTableAndNamesWhatIsMissing) {
  dir_.write("src/mine.csv", "strategy,samples,seconds,relMSE\na,1,0.1,0.5\na,4,0.4,0.1\n");
  ASSERT_TRUE(build("```plot csv=mine.csv scene=scene.dae\n```\n").problems.empty());
  EXPECT_EQ(runs(), 0);
  expect_one(build("```plot csv=gone.csv\n```\n"), 1, "no table 'gone.csv'");
  expect_one(build("```plot\n```\n"), 1, "plot needs csv=FILE");
}

TEST_F(WebsiteBuild, HungRenderIsStoppedAtTheTimeLimit) {
  auto r = build("# T\n\n```render scene=scene.dae flags=\"--hang\"\n```\n", false, 1);
  expect_one(r, 3, "time limit of 1 s");
}

TEST_F(WebsiteBuild, SampleRateImageHasItsColourKey) {
  auto r = build("```render scene=scene.dae flags=\"-r 20 10 -s 64 -a 8 0.05\" extras=yes\n```\n");
  ASSERT_TRUE(r.problems.empty()) << all(r.problems);
  std::string html = page();
  EXPECT_NE(html.find("class=\"rate-key\" style=\"width:20px\""), std::string::npos) << html;
  EXPECT_NE(html.find("<span>64</span>"), std::string::npos);
  EXPECT_NE(html.find("12.5 samples per pixel on average"), std::string::npos);
}
