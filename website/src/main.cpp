// website: builds a student's write-up into a self-contained folder, starts one, or checks a
// folder made by hand.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "website/src/figure_html.h"
#include "website/src/handbook.h"
#include "website/src/site_builder.h"
#include "website/src/site_checks.h"
#include "website/src/starter.h"

namespace fs = std::filesystem;

namespace {

fs::path executable_dir() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : self.parent_path();
}

/// Scenes named in a write-up are looked for beside it, then in these folders: the project's
/// scenes, the build's generated ones (dense_mesh) and the course's, when they are there.
std::vector<fs::path> default_scene_dirs() {
  std::vector<fs::path> dirs = {PT_PROJECT_SCENES_DIR, executable_dir() / ".." / "scenes",
                                PT_COURSE_SCENES_DIR};
  std::vector<fs::path> present;
  for (const fs::path& d : dirs) {
    if (fs::is_directory(d)) present.push_back(fs::weakly_canonical(d));
  }
  return present;
}

int print_problems(const std::vector<pt::web::Problem>& problems, const std::string& what) {
  for (const auto& p : problems) std::cerr << p.to_string() << "\n";
  if (problems.empty()) return 0;
  std::cerr << "website: " << what << ": " << problems.size() << " problem"
            << (problems.size() == 1 ? "" : "s") << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Builds a path tracer write-up (Markdown with renders, grids, plots and math) into "
               "a self-contained folder, and checks such folders before they are submitted."};
  app.require_subcommand(1);

  pt::web::BuildOptions build;
  build.web_dir = PT_WEBSITE_DIR;
  build.pathtracer = executable_dir() / ".." / "app" / "pathtracer";
  std::vector<fs::path> extra_scenes;
  auto* b = app.add_subcommand("build", "Render a write-up into a folder and check it");
  b->add_option("source", build.source, "The write-up's Markdown file")->required()->check(CLI::ExistingFile);
  b->add_option("-o,--out", build.out_dir, "The folder to write (default: site beside the source)");
  b->add_option("--pathtracer", build.pathtracer, "The pathtracer executable the renders run")
      ->capture_default_str();
  b->add_option("--cache", build.cache_dir,
                "Where renders are kept between builds (default: .render-cache beside the source)");
  b->add_option("--scenes", extra_scenes, "More folders to look for scenes in");
  b->add_option("--web-dir", build.web_dir, "The website/ folder (template, KaTeX)")
      ->capture_default_str();
  b->add_option("--bench", build.bench,
                "The bench executable that measures error against time for a plot with scene= "
                "(default: beside the pathtracer)");
  b->add_flag("--quick", build.quick,
              "A draft: every render at half its width and height (about a quarter of the time)");
  b->add_option("--time-limit", build.time_limit_seconds,
                "Stop a render or a measurement that runs longer than this many seconds (0: none)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);

  pt::web::StarterOptions init;
  auto* i = app.add_subcommand("init", "Write a starting write-up with a section per part");
  i->add_option("dir", init.dir, "Folder for writeup.md")->required();
  i->add_option("--convergence", init.convergence_table,
                "Part 5's convergence table (strategy,samples,seconds,relMSE) to plot")
      ->check(CLI::ExistingFile);
  i->add_option("--scenes", extra_scenes, "More folders to look for scenes in");
  i->add_flag("--force", init.force, "Replace an existing writeup.md");

  fs::path check_dir;
  pt::web::HandbookOptions handbook;
  auto* h = app.add_subcommand("handbook", "Build the handout's pages (README and one per part) into a folder");
  h->add_option("pages", handbook.pages_dir, "The pages' folder (docs/handout)")->required()->check(CLI::ExistingDirectory);
  h->add_option("-o,--out", handbook.out_dir, "The folder to write")->required();
  h->add_option("--project", handbook.project_root,
                "The project the pages' links point into (default: two folders above the pages)");

  auto* c = app.add_subcommand("check", "Check a folder before submitting it");
  c->add_option("dir", check_dir, "The folder holding index.html")->required()->check(CLI::ExistingDirectory);

  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<fs::path> scene_dirs = extra_scenes;
    for (const fs::path& d : default_scene_dirs()) scene_dirs.push_back(d);
    if (*b) {
      fs::path src_dir = build.source.parent_path().empty() ? "." : build.source.parent_path();
      if (build.out_dir.empty()) build.out_dir = src_dir / "site";
      if (build.cache_dir.empty()) build.cache_dir = src_dir / ".render-cache";
      build.pathtracer = fs::weakly_canonical(build.pathtracer);
      if (build.bench.empty()) build.bench = build.pathtracer.parent_path() / "bench";
      build.bench = fs::weakly_canonical(build.bench);
      build.scene_dirs = scene_dirs;
      build.log = &std::cerr;
      auto report = pt::web::build_site(build);
      int rc = print_problems(report.problems, "build failed");
      if (rc == 0) {
        std::cerr << "website: wrote " << (build.out_dir / "index.html").string() << " ("
                  << report.renders_made << " renders made, " << report.renders_cached
                  << " from the cache; " << pt::web::seconds_text(report.render_seconds)
                  << " of rendering in all" << (build.quick ? ", draft sizes" : "") << ")\n";
      }
      return rc;
    }
    if (*i) {
      init.scene_dirs = scene_dirs;
      fs::path file = pt::web::write_starter(init);
      std::cerr << "website: wrote " << file.string() << "; build it with: website build "
                << file.string() << "\n";
      return 0;
    }
    if (*h) {
      if (handbook.project_root.empty()) handbook.project_root = handbook.pages_dir / ".." / "..";
      handbook.web_dir = build.web_dir;
      handbook.pathtracer = fs::weakly_canonical(build.pathtracer);
      handbook.log = &std::cerr;
      auto report = pt::web::build_handbook(handbook);
      int rc = print_problems(report.problems, "handbook failed");
      if (rc == 0)
        std::cerr << "website: wrote " << report.pages.size() << " pages to " << handbook.out_dir.string()
                  << " (" << report.sources.size() << " source files linked)\n";
      return rc;
    }
    if (*c) {
      int rc = print_problems(pt::web::check_folder(check_dir), "check failed");
      if (rc == 0) std::cerr << "website: " << check_dir.string() << " passes every check\n";
      return rc;
    }
  } catch (const std::exception& e) {
    std::cerr << "website: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
