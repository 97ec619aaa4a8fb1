// Typesets the write-up's TeX offline: KaTeX (from website/node_modules) renders every span at
// build time, and its stylesheet and fonts are copied beside index.html.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "website/src/math_spans.h"

namespace pt::web {

/// One typeset span: its HTML, or KaTeX's complaint about the TeX.
struct TypesetMath {
  std::string html;
  std::string error;
};

/// Runs KaTeX through node on a batch of spans and installs its assets in a folder.
class KatexMath {
 public:
  /// `web_dir` holds assets/render_math.js and node_modules/katex (the website/ folder).
  explicit KatexMath(std::filesystem::path web_dir);

  /// Typesets every span in one node run. Throws std::runtime_error when node or KaTeX is
  /// missing (with the set-up command that installs them).
  std::vector<TypesetMath> typeset(const std::vector<MathSpan>& spans) const;

  /// Copies katex.min.css and its fonts to `folder`/katex; returns the stylesheet's path
  /// relative to `folder`.
  std::string install_assets(const std::filesystem::path& folder) const;

 private:
  std::filesystem::path web_dir_;
};

}  // namespace pt::web
