// Math spans are found where a reader means math and nowhere else, and lines map back.
#include "website/src/math_spans.h"

#include <gtest/gtest.h>

using pt::web::MathSpan;
using pt::web::math_token;
using pt::web::protect_math;

TEST(WebsiteMath, InlineAndDisplaySpansBecomeTokens) {
  std::vector<MathSpan> spans;
  auto p = protect_math("Here $s = 1, l = 4$ and\n$$\\int_0^1 x_i\\,dx$$ end\n", spans);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].tex, "s = 1, l = 4");
  EXPECT_FALSE(spans[0].display);
  EXPECT_EQ(spans[1].tex, "\\int_0^1 x_i\\,dx");
  EXPECT_TRUE(spans[1].display);
  EXPECT_EQ(spans[1].line, 2);
  EXPECT_EQ(p.text, "Here " + math_token(0) + " and\n" + math_token(1) + " end\n");
}

TEST(WebsiteMath, DollarsThatAreNotMathStayText) {
  std::vector<MathSpan> spans;
  auto p = protect_math("costs $5 and $10, or \\$x\\$, or $ x $\n", spans);
  EXPECT_TRUE(spans.empty());
  EXPECT_EQ(p.text, "costs $5 and $10, or \\$x\\$, or $ x $\n");
}

TEST(WebsiteMath, CodeIsLeftAlone) {
  std::vector<MathSpan> spans;
  std::string src = "`$a$` and ``$b$``\n\n```\n$c$\n```\n\n~~~~\n$$d$$\n~~~~\nafter $e$\n";
  auto p = protect_math(src, spans);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].tex, "e");
  EXPECT_EQ(spans[0].line, 10);
}

TEST(WebsiteMath, InlineMathDoesNotCrossABlankLine) {
  std::vector<MathSpan> spans;
  protect_math("a $x\n\ny$ b\n", spans);
  EXPECT_TRUE(spans.empty());
  protect_math("a $x\ny$ b\n", spans);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].tex, "x\ny");
}

TEST(WebsiteMath, LineMapSkipsTheLinesOfMultiLineMath) {
  std::vector<MathSpan> spans;
  auto p = protect_math("one\n$$\na\nb\n$$\nsix\n", spans);
  // The protected text has "six" on its line 3; in the source it is on line 6.
  EXPECT_EQ(p.text, "one\n" + math_token(0) + "\nsix\n");
  EXPECT_EQ(p.source_line(1), 1);
  EXPECT_EQ(p.source_line(2), 2);
  EXPECT_EQ(p.source_line(3), 6);
}
