// Finds the $inline$ and $$display$$ math of a Markdown source and swaps each for a plain token
// before cmark sees it, so that Markdown never reads a '_' or '*' of TeX as emphasis.
#pragma once

#include <string>
#include <vector>

namespace pt::web {

/// One piece of TeX and where it was written.
struct MathSpan {
  std::string tex;
  bool display = false;
  int line = 0;  ///< 1-based line of the source where the span starts
};

/// A Markdown text with its math swapped out, and the way back to the source's lines.
struct ProtectedMarkdown {
  std::string text;            ///< what cmark parses
  std::vector<int> line_map;   ///< line_map[k] = source line of line k of `text` (index 0 unused)
  int source_line(int line) const;
};

/// The token that stands for span number `index`: letters and digits only, which Markdown
/// leaves alone.
std::string math_token(size_t index);

/// Swaps the math of `markdown` for tokens, appending the spans to `spans` (token numbers
/// continue from spans.size()). Code spans and fenced code blocks are left as they are; `\$`
/// is a dollar sign; a '$' followed by a space or a closing '$' followed by a digit is not math,
/// so "costs $5 and $10" stays text.
ProtectedMarkdown protect_math(const std::string& markdown, std::vector<MathSpan>& spans);

/// The same for a one-line text such as a caption written at `line`.
std::string protect_inline_math(const std::string& text, int line, std::vector<MathSpan>& spans);

}  // namespace pt::web
