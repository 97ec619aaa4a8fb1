#include "website/src/handbook.h"

#include <algorithm>
#include <fstream>
#include <ostream>
#include <system_error>

#include "framework/text/markdown_links.h"
#include "framework/text/text_file.h"
#include "website/src/site_builder.h"

namespace fs = std::filesystem;

namespace pt::web {
namespace {

std::string html_name(const std::string& page) {
  return page == "README.md" ? "index.html" : fs::path(page).replace_extension(".html").string();
}

/// One link target, made to work in the handbook's folder.
std::string rewrite(const std::string& target, const fs::path& page_dir,
                    const std::set<std::string>& page_names, std::set<std::string>* sources,
                    std::vector<std::string>* outside) {
  if (!is_relative_link(target)) return target;
  const size_t hash = target.find('#');
  const std::string file = target.substr(0, hash);
  const std::string anchor = hash == std::string::npos ? "" : target.substr(hash);
  const fs::path in_project = (page_dir / file).lexically_normal();
  if (in_project.empty() || *in_project.begin() == "..") {
    outside->push_back(target);
    return target;
  }
  if (in_project.parent_path() == page_dir.lexically_normal() &&
      page_names.count(in_project.filename().string()))
    return html_name(in_project.filename().string()) + anchor;
  sources->insert(in_project.generic_string());
  return "source/" + in_project.generic_string() + anchor;
}

void copy_tree_into(const fs::path& from, const fs::path& to, bool skip_top_html) {
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(from)) {
    const fs::path rel = e.path().lexically_relative(from);
    if (skip_top_html && rel.parent_path().empty() && rel.extension() == ".html") continue;
    const fs::path dst = to / rel;
    if (e.is_directory()) {
      fs::create_directories(dst);
    } else if (!fs::exists(dst)) {
      fs::create_directories(dst.parent_path());
      fs::copy_file(e.path(), dst);
    }
  }
}

}  // namespace

std::string handbook_markdown(const std::string& markdown, const fs::path& page_dir,
                              const std::set<std::string>& page_names,
                              std::set<std::string>* sources, std::vector<std::string>* outside) {
  return rewrite_markdown_links(markdown, [&](const std::string& target) {
    return rewrite(target, page_dir, page_names, sources, outside);
  });
}

HandbookReport build_handbook(const HandbookOptions& options) {
  HandbookReport report;
  std::vector<std::string> pages;
  for (const fs::directory_entry& e : fs::directory_iterator(options.pages_dir))
    if (e.is_regular_file() && e.path().extension() == ".md") pages.push_back(e.path().filename().string());
  std::sort(pages.begin(), pages.end(), [](const std::string& a, const std::string& b) {
    return (a == "README.md") != (b == "README.md") ? a == "README.md" : a < b;
  });
  if (pages.empty() || pages.front() != "README.md") {
    report.problems.push_back({options.pages_dir, 0, "holds no README.md, the handbook's first page"});
    return report;
  }
  const std::set<std::string> names(pages.begin(), pages.end());
  const fs::path root = fs::weakly_canonical(options.project_root);
  const fs::path page_dir = fs::weakly_canonical(options.pages_dir).lexically_relative(root);

  const fs::path out = options.out_dir;
  if (fs::exists(out) && !fs::is_empty(out) && !fs::exists(out / "index.html")) {
    report.problems.push_back({out, 0, "is not empty and holds no index.html: refusing to replace it"});
    return report;
  }
  fs::remove_all(out);
  fs::create_directories(out);
  // Each page is built on its own by build_site from a staging folder that holds every page's
  // Markdown, a stand-in for every page's HTML (so links between pages resolve) and the sources.
  const fs::path stage = out.parent_path() / (out.filename().string() + ".stage");
  fs::remove_all(stage);
  fs::create_directories(stage);
  std::vector<std::string> outside;
  for (const std::string& page : pages) {
    const std::string text = read_text_file(options.pages_dir / page);
    std::ofstream(stage / page) << handbook_markdown(text, page_dir, names, &report.sources, &outside);
    std::ofstream(stage / html_name(page)) << "<!doctype html><title>stand-in</title>\n";
  }
  for (const std::string& target : outside)
    report.problems.push_back({options.pages_dir, 0, "'" + target + "' leaves the project"});
  for (const std::string& rel : report.sources) {
    const fs::path from = root / rel, to = stage / "source" / rel;
    if (!fs::is_regular_file(from)) continue;  // the page's own check names it, with its line
    fs::create_directories(to.parent_path());
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  }
  for (const std::string& page : pages) {
    BuildOptions b;
    b.source = stage / page;
    b.out_dir = stage / "out" / fs::path(page).stem();
    b.web_dir = options.web_dir;
    b.pathtracer = options.pathtracer;
    b.cache_dir = stage / "cache";
    b.log = options.log;
    BuildReport built = build_site(b);
    for (Problem p : built.problems) {
      if (p.file == b.source) p.file = options.pages_dir / page;
      report.problems.push_back(p);
    }
    if (!built.problems.empty()) continue;
    fs::copy_file(b.out_dir / "index.html", out / html_name(page));
    copy_tree_into(b.out_dir, out, true);
    report.pages.push_back(html_name(page));
  }
  fs::remove_all(stage);
  if (report.problems.empty())
    for (const Problem& p : check_folder(out)) report.problems.push_back(p);
  return report;
}

}  // namespace pt::web
