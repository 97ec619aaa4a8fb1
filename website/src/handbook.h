// `website handbook`: the student's handout pages (docs/handout/*.md) as one small website, the
// README as index.html and a page per part, with the source files they point at copied in.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <set>
#include <string>
#include <vector>

#include "website/src/site_checks.h"

namespace pt::web {

/// Where the handbook is read from and written to.
struct HandbookOptions {
  std::filesystem::path pages_dir;     ///< the pages: README.md and part*.md (docs/handout)
  std::filesystem::path project_root;  ///< what the pages' relative links to code resolve in
  std::filesystem::path out_dir;       ///< the folder to write (replaced if it holds a site)
  std::filesystem::path web_dir;       ///< website/: assets/ and node_modules/katex
  std::filesystem::path pathtracer;    ///< only used if a page renders (none does today)
  std::ostream* log = nullptr;
};

/// What a build made; it succeeded when `problems` is empty.
struct HandbookReport {
  std::vector<Problem> problems;
  std::vector<std::string> pages;    ///< the HTML pages written, index.html first
  std::set<std::string> sources;     ///< project files copied in, relative to the project
};

/// A page's Markdown with its links made to work inside the handbook's folder: a link to another
/// page (part3.md, README.md) goes to its HTML page (part3.html, index.html); a link to a file of
/// the project goes to its copy under source/ (source/parts/3-direct/direct_lighting.cpp), and is
/// recorded in `sources` (relative to the project root). `page_dir` is the page's folder relative
/// to the project root. Links that leave the project are recorded in `outside`, unchanged.
/// Code spans and fenced blocks are left alone.
std::string handbook_markdown(const std::string& markdown, const std::filesystem::path& page_dir,
                              const std::set<std::string>& page_names,
                              std::set<std::string>* sources, std::vector<std::string>* outside);

/// Builds every page (README.md first, then the others in name order) and checks the folder as
/// `website check` would. Problems name the page's own file and line.
HandbookReport build_handbook(const HandbookOptions& options);

}  // namespace pt::web
