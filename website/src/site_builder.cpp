#include "website/src/site_builder.h"

#include <cmark.h>
#include <sys/stat.h>

#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>

#include "framework/plot/convergence_plot.h"
#include "framework/text/text_file.h"
#include "framework/text/xml_text.h"
#include "website/src/directive.h"
#include "website/src/katex_math.h"
#include "website/src/math_spans.h"
#include "website/src/render_cache.h"

namespace fs = std::filesystem;

namespace pt::web {
namespace {

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size())) {
    s.replace(pos, from.size(), to);
  }
}

/// A problem at a line of the source, carried out of the directive code as an exception.
struct SourceError {
  int line;
  std::string message;
};

/// The state of one build: the parsed source, where things go, and what went wrong.
class SiteBuilder {
 public:
  explicit SiteBuilder(const BuildOptions& o) : opt_(o), src_dir_(o.source.parent_path()) {
    if (src_dir_.empty()) src_dir_ = ".";
  }

  BuildReport run() {
    if (!fs::is_regular_file(opt_.source)) {
      report_.problems.push_back({opt_.source, 0, "no such write-up source"});
      return report_;
    }
    std::string markdown = read_text_file(opt_.source);
    prepare_output();
    protected_ = protect_math(markdown, math_);
    std::unique_ptr<cmark_node, void (*)(cmark_node*)> doc(
        cmark_parse_document(protected_.text.data(), protected_.text.size(),
                             CMARK_OPT_DEFAULT | CMARK_OPT_UNSAFE),
        cmark_node_free);
    title_ = "Write-up";
    walk(doc.get());
    char* rendered = cmark_render_html(doc.get(), CMARK_OPT_DEFAULT | CMARK_OPT_UNSAFE);
    std::string body = rendered;
    free(rendered);
    body = typeset_math(body);
    write_page(body);
    if (report_.problems.empty()) {
      // The folder as written must pass the same checks as a hand-made one.
      for (Problem& p : check_folder(opt_.out_dir)) report_.problems.push_back(p);
    }
    return report_;
  }

 private:
  void problem(int source_line, const std::string& message) {
    report_.problems.push_back({opt_.source, source_line, message});
  }

  /// Files the generator writes itself get the permissions a web server needs.
  void publish(const fs::path& p) {
    fs::permissions(p, fs::is_directory(p) ? fs::perms(0755) : fs::perms(0644));
  }

  fs::path make_dir(const fs::path& d) {
    fs::create_directories(d);
    for (fs::path at = d; at != opt_.out_dir.parent_path() && !at.empty(); at = at.parent_path()) {
      publish(at);
      if (at == opt_.out_dir) break;
    }
    return d;
  }

  void prepare_output() {
    const fs::path& out = opt_.out_dir;
    if (fs::exists(out) && !fs::is_empty(out)) {
      if (!fs::exists(out / "index.html")) {
        throw std::runtime_error(out.string() +
                                 " is not empty and holds no index.html: refusing to replace it");
      }
      fs::remove_all(out);  // a site made before: rebuild it from scratch, so nothing stale stays
    }
    make_dir(out);
  }

  // --- the Markdown tree -------------------------------------------------------------------

  void walk(cmark_node* doc) {
    std::vector<cmark_node*> blocks, refs, html;
    cmark_iter* it = cmark_iter_new(doc);
    for (cmark_event_type ev; (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
      if (ev != CMARK_EVENT_ENTER) continue;
      cmark_node* n = cmark_iter_get_node(it);
      switch (cmark_node_get_type(n)) {
        case CMARK_NODE_CODE_BLOCK: blocks.push_back(n); break;
        case CMARK_NODE_IMAGE:
        case CMARK_NODE_LINK: refs.push_back(n); break;
        case CMARK_NODE_HTML_BLOCK:
        case CMARK_NODE_HTML_INLINE: html.push_back(n); break;
        case CMARK_NODE_HEADING:
          if (!have_title_ && cmark_node_get_heading_level(n) == 1) {
            title_ = plain_text(n);
            have_title_ = true;
          }
          break;
        default: break;
      }
    }
    cmark_iter_free(it);
    for (cmark_node* n : refs) {
      bool image = cmark_node_get_type(n) == CMARK_NODE_IMAGE;
      FoundReference ref{cmark_node_get_url(n) ? cmark_node_get_url(n) : "", line_of(n), image};
      use_source_file(ref);
    }
    for (cmark_node* n : html) {
      const char* lit = cmark_node_get_literal(n);
      for (FoundReference ref : find_html_references(lit ? lit : "")) {
        ref.line += line_of(n) - 1;
        use_source_file(ref);
      }
    }
    for (cmark_node* n : blocks) directive_block(n);
  }

  /// The source line of a node; inline nodes carry no position in cmark, so their block's.
  int line_of(cmark_node* n) {
    for (cmark_node* at = n; at; at = cmark_node_parent(at)) {
      if (int l = cmark_node_get_start_line(at); l > 0) return protected_.source_line(l);
    }
    return 0;
  }

  std::string plain_text(cmark_node* n) {
    std::string text;
    cmark_iter* it = cmark_iter_new(n);
    for (cmark_event_type ev; (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
      cmark_node* c = cmark_iter_get_node(it);
      if (ev == CMARK_EVENT_ENTER && (cmark_node_get_type(c) == CMARK_NODE_TEXT ||
                                      cmark_node_get_type(c) == CMARK_NODE_CODE)) {
        text += cmark_node_get_literal(c);
      }
    }
    cmark_iter_free(it);
    for (size_t i = 0; i < math_.size(); ++i) replace_all(text, math_token(i), math_[i].tex);
    return text;
  }

  /// A file the source names (image, link, raw HTML src): checked where the student wrote it,
  /// then copied to the same relative place in the output.
  void use_source_file(const FoundReference& ref) {
    size_t before = report_.problems.size();
    auto file = check_reference(src_dir_, src_dir_, ref, opt_.source, report_.problems);
    if (!file || report_.problems.size() != before) return;
    fs::path rel = file->lexically_relative(src_dir_);
    fs::path to = opt_.out_dir / rel;
    if (fs::exists(to)) return;
    make_dir(to.parent_path());
    fs::copy_file(*file, to);  // keeps the student's permissions, which the check has vetted
  }

  // --- directives --------------------------------------------------------------------------

  void directive_block(cmark_node* n) {
    const char* info = cmark_node_get_fence_info(n);
    Directive d;
    int line = line_of(n);
    try {
      d = parse_directive(info ? info : "");
    } catch (const DirectiveError& e) {
      problem(line, e.what());
      return;
    }
    if (d.name != "render" && d.name != "grid" && d.name != "plot") return;  // ordinary code
    std::string body = cmark_node_get_literal(n) ? cmark_node_get_literal(n) : "";
    std::string html;
    try {
      if (d.name == "render") html = render_figure(d, line, "render");
      if (d.name == "grid") html = grid_figure(d, body, line);
      if (d.name == "plot") html = plot_figure(d, line);
    } catch (const SourceError& e) {
      problem(e.line, e.message);
      return;
    } catch (const DirectiveError& e) {
      problem(line, e.what());
      return;
    }
    cmark_node* block = cmark_node_new(CMARK_NODE_HTML_BLOCK);
    cmark_node_set_literal(block, html.c_str());
    cmark_node_replace(n, block);
    cmark_node_free(n);
  }

  std::string caption_html(const std::string& caption, int line) {
    return xml_escape(protect_inline_math(caption, line, math_));
  }

  fs::path find_scene(const std::string& name, int line) {
    if (name.empty()) throw SourceError{line, "render needs scene=FILE"};
    std::vector<fs::path> dirs = {src_dir_};
    dirs.insert(dirs.end(), opt_.scene_dirs.begin(), opt_.scene_dirs.end());
    std::string tried;
    for (const fs::path& d : dirs) {
      if (fs::is_regular_file(d / name)) return d / name;
      tried += "\n  " + (d / name).string();
    }
    throw SourceError{line, "scene '" + name + "' not found; looked for" + tried};
  }

  RenderCache& cache(int line) {
    if (!cache_) {
      try {
        cache_ = std::make_unique<RenderCache>(opt_.pathtracer, opt_.cache_dir);
      } catch (const RenderError& e) {
        throw SourceError{line, e.what()};
      }
    }
    return *cache_;
  }

  /// One render's <figure>: the image, the caption, and how it was made.
  std::string render_figure(const Directive& d, int line, const std::string& css_class) {
    for (const auto& [key, value] : d.attributes) {
      if (key != "scene" && key != "flags" && key != "caption" && key != "extras" &&
          key != "image") {
        throw SourceError{line, "unknown attribute '" + key +
                                    "' (a render takes scene, flags, caption, extras)"};
      }
    }
    std::string caption = caption_html(d.get("caption"), line);
    if (d.attributes.count("image")) {
      FoundReference ref{d.get("image"), line, true};
      size_t before = report_.problems.size();
      use_source_file(ref);
      if (report_.problems.size() != before) return "";
      return "<figure class=\"" + css_class + "\"><img src=\"" + xml_escape(ref.target) +
             "\" alt=\"" + xml_escape(d.get("caption")) + "\"><figcaption>" + caption +
             "</figcaption></figure>";
    }
    fs::path scene = find_scene(d.get("scene"), line);
    CachedRender r;
    try {
      r = cache(line).render(scene, d.get("flags"));
    } catch (const RenderError& e) {
      throw SourceError{line, e.what()};
    } catch (const DirectiveError& e) {
      throw SourceError{line, e.what()};
    }
    (r.from_cache ? report_.renders_cached : report_.renders_made)++;
    if (opt_.log) {
      *opt_.log << "website: " << (r.from_cache ? "cached " : "rendered ") << r.command << " ("
                << static_cast<int>(r.seconds * 10 + 0.5) / 10.0 << " s)\n";
    }
    std::string stem = scene.stem().string() + "-" + r.key.substr(0, 10);
    std::string html = "<figure class=\"" + css_class + "\">" +
                       image_html(r.image, stem + ".png", d.get("caption"));
    if (d.get("extras") == "yes") {
      for (const fs::path& extra : r.extras) {
        std::string name = stem + "-" + extra.filename().string();
        html += image_html(extra, name, extra.stem().string());
      }
    }
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f s", r.seconds);
    html += "<figcaption>" + caption + (caption.empty() ? "" : "<br>") + "<code>" +
            xml_escape(r.command) + "</code> <span class=\"time\">" + seconds +
            "</span></figcaption></figure>";
    return html;
  }

  std::string image_html(const fs::path& from, const std::string& name, const std::string& alt) {
    fs::path dir = make_dir(opt_.out_dir / "renders");
    fs::copy_file(from, dir / name, fs::copy_options::overwrite_existing);
    publish(dir / name);
    return "<img src=\"renders/" + xml_escape(name) + "\" alt=\"" + xml_escape(alt) + "\">";
  }

  /// Renders side by side: the header's scene and flags are shared, each line adds its own.
  std::string grid_figure(const Directive& d, const std::string& body, int line) {
    int columns = 0;
    try {
      columns = std::stoi(d.get("columns", "0"));
    } catch (const std::exception&) {
      throw SourceError{line, "columns must be a number, not '" + d.get("columns") + "'"};
    }
    std::string cells;
    int count = 0;
    std::istringstream lines(body);
    int k = 0;
    for (std::string text; std::getline(lines, text);) {
      ++k;
      if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
      int cell_line = line + k;
      Directive cell;
      try {
        cell = parse_directive(text, false);
      } catch (const DirectiveError& e) {
        throw SourceError{cell_line, e.what()};
      }
      if (!cell.attributes.count("image")) {
        if (!cell.attributes.count("scene")) cell.attributes["scene"] = d.get("scene");
        try {
          cell.attributes["flags"] = merge_flags(d.get("flags"), cell.get("flags"));
        } catch (const DirectiveError& e) {
          throw SourceError{cell_line, e.what()};
        }
      }
      try {
        cells += render_figure(cell, cell_line, "cell") + "\n";
      } catch (const SourceError& e) {
        problem(e.line, e.message);  // one bad cell does not hide the others' problems
      }
      ++count;
    }
    if (count == 0) throw SourceError{line, "a grid needs one line per cell in its block"};
    if (columns <= 0) columns = std::min(count, 4);
    std::string caption = caption_html(d.get("caption"), line);
    return "<figure class=\"grid\"><div class=\"cells\" style=\"grid-template-columns: repeat(" +
           std::to_string(columns) + ", minmax(0, 1fr))\">\n" + cells + "</div>" +
           (caption.empty() ? "" : "<figcaption>" + caption + "</figcaption>") + "</figure>";
  }

  std::string plot_figure(const Directive& d, int line) {
    std::string table = d.get("csv", d.get("json"));
    if (table.empty()) throw SourceError{line, "plot needs csv=FILE or json=FILE"};
    fs::path file = src_dir_ / table;
    std::string axis = d.get("x", "seconds");
    if (axis != "seconds" && axis != "samples") {
      throw SourceError{line, "x must be seconds or samples, not '" + axis + "'"};
    }
    std::string svg;
    try {
      auto rows = read_convergence_table(file);
      svg = convergence_svg(rows, axis == "seconds" ? PlotAxis::seconds : PlotAxis::samples,
                            d.get("title", "Error against " + axis), file.string());
    } catch (const PlotError& e) {
      throw SourceError{line, std::string("plot: ") + e.what()};
    }
    fs::path dir = make_dir(opt_.out_dir / "plots");
    std::string name = fs::path(table).stem().string() + "-" + axis + ".svg";
    std::ofstream(dir / name) << svg;
    publish(dir / name);
    std::string caption = caption_html(d.get("caption"), line);
    return "<figure class=\"plot\"><img src=\"plots/" + xml_escape(name) + "\" alt=\"" +
           xml_escape(d.get("title", "convergence plot")) + "\">" +
           (caption.empty() ? "" : "<figcaption>" + caption + "</figcaption>") + "</figure>";
  }

  // --- math and the page -------------------------------------------------------------------

  std::string typeset_math(std::string body) {
    if (math_.empty()) return body;
    KatexMath katex(opt_.web_dir);
    std::vector<TypesetMath> out;
    try {
      out = katex.typeset(math_);
    } catch (const std::exception& e) {
      problem(math_.front().line, e.what());
      return body;
    }
    for (size_t i = 0; i < math_.size(); ++i) {
      if (!out[i].error.empty()) {
        problem(math_[i].line, "math $" + math_[i].tex + "$: " + out[i].error);
        continue;
      }
      std::string token = math_token(i);
      if (math_[i].display) {
        replace_all(body, "<p>" + token + "</p>", "<div class=\"math-display\">" + token + "</div>");
      }
      replace_all(body, token, out[i].html);
    }
    katex_css_ = katex.install_assets(opt_.out_dir);
    for (const auto& e : fs::recursive_directory_iterator(opt_.out_dir / "katex")) publish(e.path());
    publish(opt_.out_dir / "katex");
    return body;
  }

  void write_page(const std::string& body) {
    std::string page = read_text_file(opt_.web_dir / "assets" / "template.html");
    if (page.empty()) {
      throw std::runtime_error("the page template " +
                               (opt_.web_dir / "assets" / "template.html").string() +
                               " is missing or empty");
    }
    std::string css_links;
    if (!katex_css_.empty()) css_links += "<link rel=\"stylesheet\" href=\"" + katex_css_ + "\">\n";
    css_links += "<link rel=\"stylesheet\" href=\"style.css\">";
    replace_all(page, "{{title}}", xml_escape(title_));
    replace_all(page, "{{stylesheets}}", css_links);
    replace_all(page, "{{body}}", body);
    fs::copy_file(opt_.web_dir / "assets" / "style.css", opt_.out_dir / "style.css",
                  fs::copy_options::overwrite_existing);
    publish(opt_.out_dir / "style.css");
    std::ofstream(opt_.out_dir / "index.html") << page;
    publish(opt_.out_dir / "index.html");
  }

  const BuildOptions& opt_;
  fs::path src_dir_;
  BuildReport report_;
  ProtectedMarkdown protected_;
  std::vector<MathSpan> math_;
  std::unique_ptr<RenderCache> cache_;
  std::string title_, katex_css_;
  bool have_title_ = false;
};

}  // namespace

BuildReport build_site(const BuildOptions& options) { return SiteBuilder(options).run(); }

}  // namespace pt::web
