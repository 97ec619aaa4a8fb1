// Not needed for the assignment.
// Which link targets are relative, and that only links outside code are rewritten.
#include "framework/text/markdown_links.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

TEST(FrameworkMarkdownLinks, RelativeTargetsAreFilesBesideThePage) {
  EXPECT_TRUE(is_relative_link("part1.md"));
  EXPECT_TRUE(is_relative_link("../../parts/1-raygen/camera_ray.cpp#L3"));
  EXPECT_TRUE(is_relative_link("dir/a:b.md"));  // a colon after a slash is the path's
  EXPECT_FALSE(is_relative_link(""));
  EXPECT_FALSE(is_relative_link("#step-2"));
  EXPECT_FALSE(is_relative_link("/etc/passwd"));
  EXPECT_FALSE(is_relative_link("https://example.org/x.md"));
  EXPECT_FALSE(is_relative_link("mailto:staff@example.org"));
}

TEST(FrameworkMarkdownLinks, OnlyLinksOutsideCodeAreRewritten) {
  const std::string page =
      "See [the camera](a.md) and [b](b.md#x).\n"
      "Not `[code](c.md)`, but [d](d.md).\n"
      "```\n[fenced](e.md)\n```\n"
      "[after](f.md)";
  const std::string out =
      rewrite_markdown_links(page, [](const std::string& t) { return "<" + t + ">"; });
  EXPECT_EQ(out,
            "See [the camera](<a.md>) and [b](<b.md#x>).\n"
            "Not `[code](c.md)`, but [d](<d.md>).\n"
            "```\n[fenced](e.md)\n```\n"
            "[after](<f.md>)");
}

}  // namespace
}  // namespace pt
