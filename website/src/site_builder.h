// `website build`: turns a Markdown write-up into a self-contained folder (index.html, its
// images, renders, plots and the math fonts), then checks the folder as a grader's server would.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "website/src/site_checks.h"

namespace pt::web {

/// Where a build reads from and writes to.
struct BuildOptions {
  std::filesystem::path source;      ///< the write-up's Markdown file
  std::filesystem::path out_dir;     ///< the folder to write (replaced if it holds a site)
  std::filesystem::path web_dir;     ///< website/: assets/ and node_modules/katex
  std::filesystem::path pathtracer;  ///< the renderer the render directives run
  std::filesystem::path bench;       ///< the convergence study's runner (plot scene=...)
  std::filesystem::path cache_dir;   ///< where renders are kept between builds
  std::vector<std::filesystem::path> scene_dirs;  ///< searched after the source's own folder
  std::ostream* log = nullptr;       ///< progress lines (one per render), or none
  /// A draft: every render at half its width and height (a quarter of the time), the page
  /// marked as a draft. Samples, depths and captions stay what the source says.
  bool quick = false;
  int time_limit_seconds = 1800;     ///< per render or study; 0: none
};

/// What a build did; it succeeded when `problems` is empty.
struct BuildReport {
  std::vector<Problem> problems;
  int renders_made = 0;
  int renders_cached = 0;
  /// The time every distinct render and study on the page took when it was made: what
  /// building the page from an empty cache costs on that machine.
  double render_seconds = 0;
};

/// Builds the folder. Every mistake in the source (a bad directive, a render that fails, an
/// image path that would break on a server, math KaTeX cannot read) is a Problem naming the
/// source file and line; the folder is then checked as `website check` would.
BuildReport build_site(const BuildOptions& options);

}  // namespace pt::web
