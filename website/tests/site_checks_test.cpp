// `website check` on small hand-made folders: each mistake students make is reported with the
// file and the line of index.html that holds it, and a correct folder passes.
#include "website/src/site_checks.h"

#include <gtest/gtest.h>

#include "website/tests/test_folder.h"

namespace fs = std::filesystem;
using pt::web::Problem;
using pt::web::check_folder;
using pt::web::testing::TestFolder;

namespace {

/// index.html with `line3` on its third line, between two lines of ordinary markup.
std::string page(const std::string& line3) {
  return "<!DOCTYPE html>\n<html><body>\n" + line3 + "\n<p>text</p>\n</body></html>\n";
}

std::string all(const std::vector<Problem>& problems) {
  std::string s;
  for (const Problem& p : problems) s += p.to_string() + "\n";
  return s;
}

/// Exactly one problem, at index.html line 3, whose message contains `words`.
void expect_one_at_line3(const TestFolder& dir, const std::vector<Problem>& problems,
                         const std::string& words) {
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_EQ(problems[0].file, dir.path() / "index.html");
  EXPECT_EQ(problems[0].line, 3);
  EXPECT_NE(problems[0].message.find(words), std::string::npos) << problems[0].message;
  EXPECT_EQ(problems[0].to_string().rfind((dir.path() / "index.html").string() + ":3: ", 0), 0u);
}

}  // namespace

TEST(WebsiteCheck, CorrectFolderPasses) {
  TestFolder dir;
  dir.image("images/render.png");
  dir.image("photo.jpg");
  dir.write("style.css", "body { background: url('images/render.png'); }\n");
  dir.write("index.html", page("<img src=\"images/render.png\"> <img src='photo.jpg'>"
                               "<link rel=\"stylesheet\" href=\"style.css\">"
                               "<a href=\"https://example.org/course\">course</a>"
                               "<a href=\"#part1\">up</a>"));
  EXPECT_TRUE(check_folder(dir.path()).empty()) << all(check_folder(dir.path()));
}

TEST(WebsiteCheck, AbsolutePathIsReportedWithLine) {
  TestFolder dir;
  fs::path img = dir.image("render.png");
  dir.write("index.html", page("<img src=\"" + img.string() + "\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "absolute path");
}

TEST(WebsiteCheck, FileUrlAndWindowsPathAreAbsoluteToo) {
  TestFolder dir;
  dir.image("render.png");
  dir.write("index.html", page("<img src=\"file:///home/me/render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "file://");
  dir.write("index.html", page("<img src=\"C:\\Users\\me\\render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "absolute Windows path");
}

TEST(WebsiteCheck, WrongCapitalisationIsReportedWithTheRealName) {
  TestFolder dir;
  dir.image("images/render.png");
  dir.write("index.html", page("<img src=\"Images/Render.png\">"));
  auto problems = check_folder(dir.path());
  expect_one_at_line3(dir, problems, "wrong capitalisation");
  EXPECT_NE(problems[0].message.find("images"), std::string::npos) << problems[0].message;
}

TEST(WebsiteCheck, MissingFileIsReportedWithLine) {
  TestFolder dir;
  dir.write("index.html", page("<img src=\"renders/spheres.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "missing");
}

TEST(WebsiteCheck, PathLeavingTheFolderIsReported) {
  TestFolder dir;
  dir.image("render.png");
  dir.write("index.html", page("<img src=\"../render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "outside the folder");
}

TEST(WebsiteCheck, JpegNamedPngIsReported) {
  TestFolder dir;
  dir.image("render.png", ".jpg");
  dir.write("index.html", page("<img src=\"render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "really a JPEG");
}

TEST(WebsiteCheck, TextNamedPngIsReported) {
  TestFolder dir;
  dir.write("render.png", "not an image\n");
  dir.write("index.html", page("<img src=\"render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "not an image");
}

TEST(WebsiteCheck, FileOthersCannotReadIsReported) {
  TestFolder dir;
  fs::path img = dir.image("render.png");
  fs::permissions(img, fs::perms(0600));
  dir.write("index.html", page("<img src=\"render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "not readable by others");
}

TEST(WebsiteCheck, FolderOthersCannotEnterIsReported) {
  TestFolder dir;
  dir.image("images/render.png");
  fs::permissions(dir.path() / "images", fs::perms(0700));
  dir.write("index.html", page("<img src=\"images/render.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "cannot enter");
}

TEST(WebsiteCheck, ImageFromTheWebIsReportedButALinkToTheWebIsNot) {
  TestFolder dir;
  dir.write("index.html", page("<img src=\"https://example.org/a.png\">"));
  expect_one_at_line3(dir, check_folder(dir.path()), "copy it into the folder");
  dir.write("index.html", page("<a href=\"https://example.org/a.png\">a</a>"));
  EXPECT_TRUE(check_folder(dir.path()).empty());
}

TEST(WebsiteCheck, StylesheetUrlsAreFollowedWithTheirOwnLines) {
  TestFolder dir;
  dir.write("style.css", "body {}\n@font-face { src: url(fonts/Main.woff2); }\n");
  dir.write("index.html", page("<link rel=\"stylesheet\" href=\"style.css\">"));
  auto problems = check_folder(dir.path());
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_EQ(problems[0].file, dir.path() / "style.css");
  EXPECT_EQ(problems[0].line, 2);
  EXPECT_NE(problems[0].message.find("missing"), std::string::npos);
}

TEST(WebsiteCheck, CommentedOutImagesAreIgnoredAndEveryProblemIsListed) {
  TestFolder dir;
  dir.write("index.html",
            "<html>\n<!-- <img src=\"old.png\"> -->\n<img src=\"/a.png\">\n<img src=\"b.png\">\n");
  auto problems = check_folder(dir.path());
  ASSERT_EQ(problems.size(), 2u) << all(problems);
  EXPECT_EQ(problems[0].line, 3);
  EXPECT_EQ(problems[1].line, 4);
}

TEST(WebsiteCheck, FolderWithoutIndexIsReported) {
  TestFolder dir;
  auto problems = check_folder(dir.path());
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("index.html"), std::string::npos);
}
