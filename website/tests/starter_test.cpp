// `website init`: the starting write-up has the five parts' sections with the renders each asks
// for, every scene it names is found, and it builds as it is.
#include "framework/testing/test_paths.h"
#include "website/src/starter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "framework/text/text_file.h"
#include "website/src/site_builder.h"
#include "website/tests/test_folder.h"

namespace fs = std::filesystem;
using pt::web::testing::TestFolder;

namespace {

pt::web::StarterOptions options(const fs::path& dir) {
  pt::web::StarterOptions o;
  o.dir = dir;
  o.scene_dirs = {fs::path(pt::test::source_dir()) / "scenes"};
  if (fs::is_directory(pt::test::shared_scenes_dir())) o.scene_dirs.push_back(pt::test::shared_scenes_dir());
  return o;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST(WebsiteInit, HasEveryPartAndTheFiguresEachAsksFor) {
  TestFolder dir;
  std::string md = pt::web::starter_markdown(options(dir.path()));
  for (int part = 1; part <= 5; ++part) {
    EXPECT_NE(md.find("## Part " + std::to_string(part) + ":"), std::string::npos) << part;
  }
  EXPECT_NE(md.find("scene=cornell_coil.dae"), std::string::npos);
  EXPECT_NE(md.find("```timing "), std::string::npos);          // with and without the BVH
  EXPECT_NE(md.find("--bvh none"), std::string::npos);
  EXPECT_NE(md.find("```compare "), std::string::npos);         // hemisphere against lights
  EXPECT_NE(md.find("flags=\"-H\""), std::string::npos);
  EXPECT_NE(md.find("minus=\"-m 1\""), std::string::npos);      // indirect light alone
  for (const char* l : {"-l 1\"", "-l 4\"", "-l 16\"", "-l 64\""}) {
    EXPECT_NE(md.find(l), std::string::npos) << l;
  }
  for (int m : {0, 1, 2, 3, 4, 5, 100}) {
    EXPECT_NE(md.find("flags=\"-m " + std::to_string(m) + "\""), std::string::npos) << m;
  }
  for (int k = 0; k <= 5; ++k) {
    EXPECT_NE(md.find("--bounce " + std::to_string(k) + "\""), std::string::npos) << k;
  }
  for (int s : {1, 2, 4, 8, 16, 64, 1024}) {
    EXPECT_NE(md.find("flags=\"-s " + std::to_string(s) + "\""), std::string::npos) << s;
  }
  EXPECT_NE(md.find("extras=yes"), std::string::npos);          // Part 5's sample-rate image
  EXPECT_NE(md.find("zoom="), std::string::npos);               // crops of the soft shadows
  // The run-time-against-error plot is always there: measured when no table is given.
  EXPECT_NE(md.find("```plot scene="), std::string::npos);
}

TEST(WebsiteInit, EveryRenderAReaderComparesIsAtLeast320PixelsWide) {
  TestFolder dir;
  std::string md = pt::web::starter_markdown(options(dir.path()));
  std::regex resolution("-r (\\d+) (\\d+)");
  int renders = 0;
  for (std::sregex_iterator it(md.begin(), md.end(), resolution), end; it != end; ++it) {
    int width = std::stoi((*it)[1]);
    // The renders without the BVH are timed, not looked at, and the study's are measured.
    size_t line_start = md.rfind('\n', it->position()) + 1;
    std::string line = md.substr(line_start, md.find('\n', it->position()) - line_start);
    if (line.find("versus=") != std::string::npos && (*it)[0] == "-r 80 60") continue;
    if (line.find("```plot") == 0) continue;
    ++renders;
    EXPECT_GE(width, 320) << line;
  }
  EXPECT_GE(renders, 8);
}

TEST(WebsiteInit, UsesTheStudentsConvergenceTableWhenGivenOne) {
  TestFolder dir;
  auto o = options(dir.path());
  o.convergence_table = dir.write("mine.csv", "strategy,samples,seconds,relMSE\na,1,0.1,0.5\n");
  std::string md = pt::web::starter_markdown(o);
  EXPECT_NE(md.find("```plot csv=mine.csv"), std::string::npos);
  EXPECT_EQ(md.find("```plot scene="), std::string::npos);
}

TEST(WebsiteInit, BuildsAsItIsWithItsMeasuredPlot) {
  TestFolder dir;
  auto o = options(dir.path() / "writeup");
  fs::path md = pt::web::write_starter(o);
  EXPECT_THROW(pt::web::write_starter(o), std::runtime_error) << "must not overwrite";
  pt::web::BuildOptions b;
  b.source = md;
  b.out_dir = dir.path() / "site";
  b.web_dir = PT_WEBSITE_DIR;
  b.pathtracer = PT_FAKE_PATHTRACER;
  b.bench = PT_FAKE_PATHTRACER;
  b.cache_dir = dir.path() / "cache";
  b.scene_dirs = o.scene_dirs;
  auto report = pt::web::build_site(b);
  std::string all;
  for (const auto& p : report.problems) all += p.to_string() + "\n";
  ASSERT_TRUE(report.problems.empty()) << all;
  const std::string html = pt::read_text_file(b.out_dir / "index.html");
  // Part 2's grid of large meshes holds what this machine has: the course's two bunnies, or the
  // project's coil where they are absent, and the dense mesh where it was built (1 to 3).
  const std::string text = pt::read_text_file(md);
  const size_t grid = text.find("```grid columns=3");
  ASSERT_NE(grid, std::string::npos) << "no grid of large meshes in Part 2";
  const size_t grid_end = text.find("\n```", grid + 1);
  const int large_meshes = count(text.substr(grid, grid_end - grid), "\nscene=");
  EXPECT_GE(large_meshes, 1);
  // Part 1: 4, Part 2: those, Part 3: 2 + 2 crops, 2 + 2, 4 + 4; Part 4: 9, 7, 6, 7 + 7;
  // Part 5: 2.
  EXPECT_EQ(count(html, "<img src=\"renders/"),
            4 + large_meshes + 4 + 4 + 8 + 9 + 7 + 6 + 14 + 2);
  EXPECT_EQ(count(html, "<img src=\"plots/"), 1);
  EXPECT_EQ(count(html, "class=\"slider\""), 1);
  EXPECT_EQ(count(html, "class=\"rate-key\""), 1);
  EXPECT_EQ(count(html, "<table><thead>"), 1);  // the BVH timing table
}

TEST(WebsiteInit, WithoutTheCourseScenesEveryFigureUsesTheProjectsOwn) {
  TestFolder dir;
  pt::web::StarterOptions o;
  o.dir = dir.path();
  o.scene_dirs = {fs::path(pt::test::source_dir()) / "scenes"};
  std::string md = pt::web::starter_markdown(o);
  EXPECT_EQ(md.find("No scene for this figure"), std::string::npos) << md;
  EXPECT_EQ(md.find("sky/"), std::string::npos);
  EXPECT_NE(md.find("```compare "), std::string::npos);
  EXPECT_NE(md.find("```timing "), std::string::npos);
  EXPECT_NE(md.find("```plot scene=cornell_spheres.dae"), std::string::npos);
  EXPECT_NE(md.find("extras=yes"), std::string::npos);
}
