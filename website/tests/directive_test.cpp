// Directive attributes and pathtracer flags are read the way they are written.
#include "website/src/directive.h"

#include <gtest/gtest.h>

using pt::web::DirectiveError;
using pt::web::merge_flags;
using pt::web::parse_directive;
using pt::web::split_flags;

TEST(WebsiteDirective, ReadsNameAndQuotedAttributes) {
  auto d = parse_directive("render scene=a.dae flags=\"-s 64 -m 5\" caption='at $s = 64$'");
  EXPECT_EQ(d.name, "render");
  EXPECT_EQ(d.get("scene"), "a.dae");
  EXPECT_EQ(d.get("flags"), "-s 64 -m 5");
  EXPECT_EQ(d.get("caption"), "at $s = 64$");
  EXPECT_EQ(d.get("missing", "x"), "x");
}

TEST(WebsiteDirective, RejectsWhatItCannotRead) {
  EXPECT_THROW(parse_directive("render scene=a.dae oops"), DirectiveError);
  EXPECT_THROW(parse_directive("render flags=\"-s 4"), DirectiveError);
  EXPECT_THROW(parse_directive("render scene=a scene=b"), DirectiveError);
}

TEST(WebsiteDirective, SplitsFlagsLikeAShell) {
  EXPECT_EQ(split_flags("  -s 64  -r 160 120 -e 'my sky.exr'"),
            (std::vector<std::string>{"-s", "64", "-r", "160", "120", "-e", "my sky.exr"}));
}

TEST(WebsiteDirective, CellFlagsReplaceSharedOnesOfTheSameName) {
  EXPECT_EQ(merge_flags("-t 0 -r 160 120 -s 4", "-r 64 48 -m 5"), "-t 0 -r 64 48 -s 4 -m 5");
  EXPECT_EQ(merge_flags("-d -1.5 -b 0.1", "-d -2"), "-d -2 -b 0.1");
  EXPECT_EQ(merge_flags("", "-H"), "-H");
}

TEST(WebsiteDirective, FlagValuesAreTheLastOfTheNamedOption) {
  EXPECT_EQ(pt::web::flag_values("-s 4 -r 320 240 --samples 64", {"-s", "--samples"}),
            (std::vector<std::string>{"64"}));
  EXPECT_EQ(pt::web::flag_values("-r 320 240", {"-r"}), (std::vector<std::string>{"320", "240"}));
  EXPECT_TRUE(pt::web::flag_values("-m 5", {"-s"}).empty());
}

TEST(WebsiteDirective, DraftsHalveTheResolutionAndNothingElse) {
  EXPECT_EQ(pt::web::halve_resolution("-t 0 -r 320 240 -s 1024 -l 4"), "-t 0 -r 160 120 -s 1024 -l 4");
  EXPECT_EQ(pt::web::halve_resolution("--resolution 1 3 -m 5"), "--resolution 1 1 -m 5");
  EXPECT_EQ(pt::web::halve_resolution("-s 16 -a 32 0.1"), "-s 16 -a 32 0.1");
}
