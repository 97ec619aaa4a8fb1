// `website init`: the starting write-up has the five parts' sections with the renders each asks
// for, every scene it names is found, and it builds as it is.
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
  o.scene_dirs = {fs::path(PT_SOURCE_DIR) / "scenes"};
  if (fs::is_directory(PT_SHARED_SCENES_DIR)) o.scene_dirs.push_back(PT_SHARED_SCENES_DIR);
  return o;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST(WebsiteInit, HasEveryPartAndTheRendersEachAsksFor) {
  TestFolder dir;
  std::string md = pt::web::starter_markdown(options(dir.path()));
  for (int part = 1; part <= 5; ++part) {
    EXPECT_NE(md.find("## Part " + std::to_string(part) + ":"), std::string::npos) << part;
  }
  EXPECT_NE(md.find("scene=cornell_spheres.dae caption=\"spheres\""), std::string::npos);
  EXPECT_NE(md.find("scene=cornell_coil.dae caption=\"coil\""), std::string::npos);
  EXPECT_NE(md.find("--bvh none"), std::string::npos);
  EXPECT_NE(md.find("flags=\"-H\""), std::string::npos);
  for (const char* l : {"-l 1\"", "-l 4\"", "-l 16\"", "-l 64\""}) {
    EXPECT_NE(md.find(l), std::string::npos) << l;
  }
  for (int m = 0; m <= 5; ++m) {
    EXPECT_NE(md.find("flags=\"-m " + std::to_string(m) + "\""), std::string::npos) << m;
  }
  for (int s : {1, 4, 16, 64, 256, 1024}) {
    EXPECT_NE(md.find("flags=\"-s " + std::to_string(s) + "\""), std::string::npos) << s;
  }
  EXPECT_NE(md.find("extras=yes"), std::string::npos);  // Part 5's sample-rate image
}

TEST(WebsiteInit, BuildsAsItIsWithAConvergencePlot) {
  TestFolder dir;
  auto table = dir.write("conv.csv", "strategy,samples,seconds,relMSE\na,1,0.1,0.5\na,4,0.4,0.1\n");
  auto o = options(dir.path() / "writeup");
  o.convergence_table = table;
  fs::path md = pt::web::write_starter(o);
  EXPECT_THROW(pt::web::write_starter(o), std::runtime_error) << "must not overwrite";
  pt::web::BuildOptions b;
  b.source = md;
  b.out_dir = dir.path() / "site";
  b.web_dir = PT_WEBSITE_DIR;
  b.pathtracer = PT_FAKE_PATHTRACER;
  b.cache_dir = dir.path() / "cache";
  b.scene_dirs = o.scene_dirs;
  auto report = pt::web::build_site(b);
  std::string all;
  for (const auto& p : report.problems) all += p.to_string() + "\n";
  ASSERT_TRUE(report.problems.empty()) << all;
  const std::string html = pt::read_text_file(b.out_dir / "index.html");
  EXPECT_GE(count(html, "<img src=\"renders/"), 3 + 4 + 2 + 4 + 2 + 6 + 6 + 1);
  EXPECT_EQ(count(html, "<img src=\"plots/"), 1);
}
