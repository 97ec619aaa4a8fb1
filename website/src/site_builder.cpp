#include "website/src/site_builder.h"

#include <cmark.h>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <regex>
#include <set>
#include <sstream>

#include "framework/plot/convergence_plot.h"
#include "framework/text/text_file.h"
#include "framework/text/xml_text.h"
#include "website/src/convergence_study.h"
#include "website/src/directive.h"
#include "website/src/figure_html.h"
#include "website/src/katex_math.h"
#include "website/src/math_spans.h"
#include "website/src/page_images.h"
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
    for (const auto& [key, seconds] : timed_) report_.render_seconds += seconds;
    write_page(draft_banner() + body + render_time_note());
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
    static const std::set<std::string> kinds = {"render", "grid", "compare", "timing", "plot"};
    if (!kinds.count(d.name)) return;  // ordinary code
    std::string body = cmark_node_get_literal(n) ? cmark_node_get_literal(n) : "";
    std::string html;
    try {
      if (d.name == "render") html = render_figure(d, line);
      if (d.name == "grid") html = grid_figure(d, body, line);
      if (d.name == "compare") html = compare_figure(d, body, line);
      if (d.name == "timing") html = timing_figure(d, body, line);
      if (d.name == "plot") html = plot_figure(d, line);
    } catch (const SourceError& e) {
      if (!e.message.empty()) problem(e.line, e.message);  // empty: reported where it was found
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

  /// Refuses an attribute the directive does not know, naming the ones it does.
  static void check_attributes(const Directive& d, int line, const std::string& what,
                               const std::vector<std::string>& known) {
    for (const auto& [key, value] : d.attributes) {
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      std::string list;
      for (size_t i = 0; i < known.size(); ++i) {
        list += (i == 0 ? "" : i + 1 == known.size() ? " and " : ", ") + known[i];
      }
      throw SourceError{line, "unknown attribute '" + key + "' (" + what + " takes " + list + ")"};
    }
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
        cache_ = std::make_unique<RenderCache>(opt_.pathtracer, opt_.cache_dir,
                                               opt_.time_limit_seconds);
      } catch (const RenderError& e) {
        throw SourceError{line, e.what()};
      }
    }
    return *cache_;
  }

  /// The flags a render is made with: the source's, at half the resolution in a draft.
  std::string effective(const std::string& flags) const {
    return opt_.quick ? halve_resolution(flags) : flags;
  }

  /// Renders (or takes from the cache), logs it and counts its time once per page.
  CachedRender rendered(const fs::path& scene, const std::string& flags, bool linear, int line) {
    CachedRender r;
    try {
      r = cache(line).render(scene, flags, linear);
    } catch (const RenderError& e) {
      throw SourceError{line, e.what()};
    } catch (const DirectiveError& e) {
      throw SourceError{line, e.what()};
    }
    if (timed_.emplace(r.key, r.seconds).second) {
      (r.from_cache ? report_.renders_cached : report_.renders_made)++;
      if (opt_.log) {
        *opt_.log << "website: " << (r.from_cache ? "cached " : "rendered ") << r.command << " ("
                  << seconds_text(r.seconds) << ")\n";
      }
    }
    return r;
  }

  /// Copies a file the generator made into renders/ (or plots/) under `name`; returns its src.
  std::string publish_as(const fs::path& from, const std::string& folder, const std::string& name) {
    fs::path dir = make_dir(opt_.out_dir / folder);
    if (from != dir / name) fs::copy_file(from, dir / name, fs::copy_options::overwrite_existing);
    publish(dir / name);
    return folder + "/" + name;
  }

  PixelSize size_of(const fs::path& file, int line) {
    try {
      return image_size(file);
    } catch (const PageImageError& e) {
      throw SourceError{line, e.what()};
    }
  }

  /// A render, a difference of two renders, or one of the student's images, ready to show.
  struct Shot {
    PageImage image;
    fs::path file;             ///< the image in the output folder
    std::string caption;       ///< HTML
    std::string command;       ///< how it was made; empty for the student's own image
    double seconds = 0;
    std::optional<RenderSummary> summary;
    std::vector<fs::path> extras;
    std::string flags;         ///< as rendered
    std::string stem;          ///< the base of its file names in renders/
  };

  Shot make_shot(const Directive& d, int line) {
    Shot s;
    s.caption = caption_html(d.get("caption"), line);
    s.image.alt = d.get("caption");
    if (d.attributes.count("image")) {
      for (const char* key : {"scene", "flags", "minus", "extras"}) {
        if (d.attributes.count(key)) {
          throw SourceError{line, std::string("image= shows a picture of yours; it takes no ") + key};
        }
      }
      FoundReference ref{d.get("image"), line, true};
      size_t before = report_.problems.size();
      use_source_file(ref);
      if (report_.problems.size() != before) throw SourceError{line, ""};
      s.image.src = ref.target;
      s.file = src_dir_ / ref.target;
      s.image.size = size_of(s.file, line);
      s.stem = fs::path(ref.target).stem().string();
      return s;
    }
    fs::path scene = find_scene(d.get("scene"), line);
    s.flags = effective(d.get("flags"));
    if (d.attributes.count("minus")) {
      // The light one render has and the other lacks (global minus direct: indirect light),
      // from their linear values; PNGs are tone-mapped and clamped, so they cannot be subtracted.
      std::string other;
      try {
        other = effective(merge_flags(d.get("flags"), d.get("minus")));
      } catch (const DirectiveError& e) {
        throw SourceError{line, e.what()};
      }
      CachedRender a = rendered(scene, s.flags, true, line);
      CachedRender b = rendered(scene, other, true, line);
      s.stem = scene.stem().string() + "-" + a.key.substr(0, 8) + "-minus-" + b.key.substr(0, 8);
      fs::path out = make_dir(opt_.out_dir / "renders") / (s.stem + ".png");
      try {
        write_difference(a.linear, b.linear, out);
      } catch (const PageImageError& e) {
        throw SourceError{line, e.what()};
      }
      s.image.src = publish_as(out, "renders", s.stem + ".png");
      s.file = out;
      s.command = a.command + "  minus  " + b.command;
      s.seconds = a.seconds + b.seconds;
    } else {
      CachedRender r = rendered(scene, s.flags, false, line);
      s.stem = scene.stem().string() + "-" + r.key.substr(0, 10);
      s.image.src = publish_as(r.image, "renders", s.stem + ".png");
      s.file = opt_.out_dir / s.image.src;
      s.command = r.command;
      s.seconds = r.seconds;
      s.summary = r.summary;
      if (d.get("extras") == "yes") s.extras = r.extras;
    }
    s.image.size = size_of(s.file, line);
    return s;
  }

  std::optional<Region> zoom_of(const Directive& d, int line) {
    if (!d.attributes.count("zoom")) return std::nullopt;
    try {
      return parse_region(d.get("zoom"));
    } catch (const std::invalid_argument& e) {
      throw SourceError{line, std::string("zoom: ") + e.what()};
    }
  }

  /// The crop of `shot` that `zoom` names, enlarged to about `width` pixels; marks the region.
  PageImage crop_of(Shot& shot, const Region& zoom, int width, int line) {
    PixelRect rect = region_pixels(zoom, shot.image.size);
    shot.image.marked = rect;
    char tag[64];
    std::snprintf(tag, sizeof tag, "%d-%d-%d-%d-%d", rect.x, rect.y, rect.width, rect.height, width);
    std::string name = shot.stem + "-zoom-" + ContentHash().add(tag).hex().substr(0, 8) + ".png";
    fs::path out = make_dir(opt_.out_dir / "renders") / name;
    PageImage crop;
    try {
      crop.size = write_zoomed_crop(shot.file, zoom, width, out);
    } catch (const PageImageError& e) {
      throw SourceError{line, e.what()};
    }
    crop.src = publish_as(out, "renders", name);
    crop.alt = "zoomed: " + shot.image.alt;
    return crop;
  }

  /// The words under a render: its caption, the command that made it and how long it took.
  std::string made_by(const Shot& s, bool with_caption = true) {
    std::string html = with_caption ? s.caption : "";
    if (s.command.empty()) return html;
    if (!html.empty()) html += "<br>";
    html += "<code>" + xml_escape(s.command) + "</code> <span class=\"time\">" +
            seconds_text(s.seconds) + "</span>";
    if (s.summary && s.summary->samples_per_pixel != std::floor(s.summary->samples_per_pixel)) {
      char spp[64];
      std::snprintf(spp, sizeof spp, "%.1f", s.summary->samples_per_pixel);
      html += " <span class=\"spp\">· " + std::string(spp) + " samples per pixel on average</span>";
    }
    return html;
  }

  /// The sample-rate image of an adaptive render with its colour key, when it has one.
  std::string extras_html(const Shot& s) {
    std::string html;
    for (const fs::path& extra : s.extras) {
      PageImage img;
      std::string name = s.stem + "-" + extra.filename().string();
      img.src = publish_as(extra, "renders", name);
      img.size = size_of(opt_.out_dir / img.src, 0);
      bool rate = extra.stem().string().size() > 5 &&
                  extra.stem().string().substr(extra.stem().string().size() - 5) == "_rate";
      img.alt = rate ? "sample-rate image: " + s.image.alt : extra.stem().string();
      html += "<div class=\"pane\">" + image_html(img);
      if (rate) {
        int max = 0;
        std::vector<std::string> v = flag_values(s.flags, {"-s", "--samples"});
        if (!v.empty()) max = std::atoi(v[0].c_str());
        html += rate_key_html(max, img.size.width);
      }
      html += "</div>";
    }
    return html;
  }

  /// One render as a figure: the image (and its crop and extras), the caption, how it was made.
  std::string shot_figure(Shot& s, const std::optional<Region>& zoom, const std::string& css_class,
                          int line) {
    std::string crop;
    if (zoom) crop = image_html(crop_of(s, *zoom, s.image.size.width, line), "crop");
    std::string style = css_class == "cell" ? " style=\"width:" + std::to_string(s.image.size.width) +
                                                  "px\""
                                            : "";
    std::string pictures = image_html(s.image) + crop;
    std::string extras = extras_html(s);
    if (!extras.empty()) pictures = "<div class=\"panes\"><div class=\"pane\">" + pictures + "</div>" + extras + "</div>";
    return "<figure class=\"" + css_class + "\"" + style + ">" + pictures + "<figcaption>" +
           made_by(s) + "</figcaption></figure>";
  }

  std::string render_figure(const Directive& d, int line) {
    check_attributes(d, line, "a render",
                     {"scene", "flags", "caption", "extras", "image", "minus", "zoom"});
    Shot s = make_shot(d, line);
    return shot_figure(s, zoom_of(d, line), "render", line);
  }

  /// The lines of a grid-like block as cells, each with the header's scene and flags laid under
  /// its own.
  std::vector<std::pair<Directive, int>> cells_of(const Directive& d, const std::string& body,
                                                  int line, const std::vector<std::string>& known,
                                                  const std::string& what) {
    std::vector<std::pair<Directive, int>> cells;
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
        problem(cell_line, e.what());
        continue;
      }
      try {
        check_attributes(cell, cell_line, what, known);
      } catch (const SourceError& e) {
        problem(e.line, e.message);
        continue;
      }
      if (!cell.attributes.count("image")) {
        if (!cell.attributes.count("scene")) cell.attributes["scene"] = d.get("scene");
        try {
          cell.attributes["flags"] = merge_flags(d.get("flags"), cell.get("flags"));
        } catch (const DirectiveError& e) {
          problem(cell_line, e.what());
          continue;
        }
      }
      cells.push_back({cell, cell_line});
    }
    return cells;
  }

  /// Renders side by side: the header's scene and flags are shared, each line adds its own.
  std::string grid_figure(const Directive& d, const std::string& body, int line) {
    check_attributes(d, line, "a grid", {"scene", "flags", "caption", "columns", "zoom"});
    int columns = 0;
    try {
      columns = std::stoi(d.get("columns", "0"));
    } catch (const std::exception&) {
      throw SourceError{line, "columns must be a number, not '" + d.get("columns") + "'"};
    }
    std::optional<Region> zoom = zoom_of(d, line);
    size_t before = report_.problems.size();
    auto cells = cells_of(d, body, line, {"scene", "flags", "caption", "extras", "image", "minus"},
                          "a grid cell");
    if (cells.empty() && report_.problems.size() == before) {
      throw SourceError{line, "a grid needs one line per cell in its block"};
    }
    // Differences first: their linear renders then serve the plain cells with the same flags.
    std::vector<std::optional<Shot>> shots(cells.size());
    for (int pass = 0; pass < 2; ++pass) {
      for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].first.attributes.count("minus") != (pass == 0 ? 1u : 0u)) continue;
        try {
          shots[i] = make_shot(cells[i].first, cells[i].second);
        } catch (const SourceError& e) {
          if (!e.message.empty()) problem(e.line, e.message);  // one bad cell hides no other
        }
      }
    }
    std::string html;
    int widest = 0;
    for (size_t i = 0; i < cells.size(); ++i) {
      if (!shots[i]) continue;
      try {
        html += shot_figure(*shots[i], zoom, "cell", cells[i].second) + "\n";
        widest = std::max(widest, shots[i]->image.size.width);
      } catch (const SourceError& e) {
        problem(e.line, e.message);
      }
    }
    std::string style;
    if (columns > 0 && widest > 0) {
      style = " style=\"max-width:" + std::to_string(columns * widest + (columns - 1) * kGap + 1) + "px\"";
    }
    std::string caption = caption_html(d.get("caption"), line);
    return "<figure class=\"grid\"><div class=\"cells\"" + style + ">\n" + html + "</div>" +
           (caption.empty() ? "" : "<figcaption>" + caption + "</figcaption>") + "</figure>";
  }

  /// Two renders of the same size under one slider, and their zoomed crops side by side.
  std::string compare_figure(const Directive& d, const std::string& body, int line) {
    check_attributes(d, line, "a comparison", {"scene", "flags", "caption", "zoom"});
    std::optional<Region> zoom = zoom_of(d, line);
    auto cells = cells_of(d, body, line, {"scene", "flags", "caption", "image", "minus"},
                          "a side of a comparison");
    if (cells.size() != 2) {
      throw SourceError{line, "a comparison needs exactly two lines, the left picture and the "
                              "right one (found " + std::to_string(cells.size()) + ")"};
    }
    Shot left = make_shot(cells[0].first, cells[0].second);
    Shot right = make_shot(cells[1].first, cells[1].second);
    if (left.image.size.width != right.image.size.width ||
        left.image.size.height != right.image.size.height) {
      throw SourceError{cells[1].second,
                        "the two sides of a comparison must be the same size: the left is " +
                            std::to_string(left.image.size.width) + "x" +
                            std::to_string(left.image.size.height) + ", the right " +
                            std::to_string(right.image.size.width) + "x" +
                            std::to_string(right.image.size.height)};
    }
    std::string crops;
    if (zoom) {
      // Each crop two thirds as wide as the pictures, so the two sit side by side below them.
      int width = left.image.size.width * 2 / 3;
      for (Shot* s : {&left, &right}) {
        PageImage crop = crop_of(*s, *zoom, width, line);
        crops += "<figure class=\"cell\" style=\"width:" + std::to_string(crop.size.width) + "px\">" +
                 image_html(crop, "crop") + "<figcaption>" + s->caption + "</figcaption></figure>";
      }
      crops = "<div class=\"cells crops\">" + crops + "</div>";
    }
    uses_slider_ = true;
    std::string caption = caption_html(d.get("caption"), line);
    return "<figure class=\"compare\">" + slider_html(left.image, left.caption, right.image, right.caption) +
           crops + "<figcaption>" + caption + (caption.empty() ? "" : "<br>") +
           "left: " + made_by(left, false) + "<br>right: " + made_by(right, false) +
           "</figcaption></figure>";
  }

  /// A table of render speeds: each line's scene rendered with the header's flags and again
  /// with `versus` laid over them, the camera rays a second of each, and their ratio.
  std::string timing_figure(const Directive& d, const std::string& body, int line) {
    check_attributes(d, line, "a timing table", {"scene", "flags", "versus", "names", "caption"});
    std::string names = d.get("names", "first|second");
    size_t bar = names.find('|');
    if (bar == std::string::npos) {
      throw SourceError{line, "names must be two column names split by '|', as in "
                              "names=\"with the BVH|without\""};
    }
    std::string first_name = names.substr(0, bar), second_name = names.substr(bar + 1);
    auto cells = cells_of(d, body, line, {"scene", "flags", "versus", "caption"}, "a timing row");
    if (cells.empty()) throw SourceError{line, "a timing table needs one line per scene"};
    std::string rows, commands;
    for (auto& [cell, cell_line] : cells) {
      try {
        fs::path scene = find_scene(cell.get("scene"), cell_line);
        std::string a_flags = effective(cell.get("flags"));
        std::string b_flags =
            effective(merge_flags(cell.get("flags"), merge_flags(d.get("versus"), cell.get("versus"))));
        CachedRender a = rendered(scene, a_flags, false, cell_line);
        CachedRender b = rendered(scene, b_flags, false, cell_line);
        double rate[2] = {0, 0};
        std::string td[2];
        int i = 0;
        for (const CachedRender* r : {&a, &b}) {
          if (!r->summary || !(r->summary->seconds > 0)) {
            throw SourceError{cell_line, "`" + r->command + "` printed no summary line "
                              "(\"render: WxH, N spp, T s\") to time it by"};
          }
          const RenderSummary& s = *r->summary;
          double rays = double(s.width) * s.height * s.samples_per_pixel;
          rate[i] = rays / s.seconds;
          char per[64];
          std::snprintf(per, sizeof per, "%.2f M", rate[i] / 1e6);
          std::string shown = rate[i] >= 1e5 ? per : thousands(std::llround(rate[i])) + " ";
          td[i] = "<td class=\"number\">" + shown + "rays/s<br><small>" +
                  thousands(std::llround(rays)) + " rays in " + seconds_text(s.seconds) +
                  "</small></td>";
          commands += "<code>" + xml_escape(r->command) + "</code><br>";
          ++i;
        }
        const double speedup = rate[0] / rate[1];
        char ratio[64];
        std::snprintf(ratio, sizeof ratio, "%.1f", speedup);
        std::string label = caption_html(cell.get("caption", scene.stem().string()), cell_line);
        rows += "<tr><th scope=\"row\">" + label + "</th>" + td[0] + td[1] +
                "<td class=\"number\">× " +
                (speedup >= 100 ? thousands(std::llround(speedup)) : std::string(ratio)) +
                "</td></tr>\n";
      } catch (const SourceError& e) {
        problem(e.line, e.message);
      }
    }
    std::string caption = caption_html(d.get("caption"), line);
    return "<figure class=\"timing\"><table><thead><tr><th>scene</th><th>" +
           caption_html(first_name, line) + "</th><th>" + caption_html(second_name, line) +
           "</th><th>speed-up</th></tr></thead><tbody>\n" + rows + "</tbody></table><figcaption>" +
           caption + (caption.empty() ? "" : "<br>") +
           "Camera rays a second of the render alone (the pathtracer's own timing, without "
           "loading the scene or building the BVH).<details><summary>The commands</summary>" +
           commands + "</details></figcaption></figure>";
  }

  /// Error against time (or samples) from a table: the student's own (csv= or json= beside the
  /// source), or one `bench convergence` makes on the spot (scene=, flags=), cached.
  std::string plot_figure(const Directive& d, int line) {
    check_attributes(d, line, "a plot", {"csv", "json", "scene", "flags", "x", "title", "caption"});
    std::string table = d.get("csv", d.get("json"));
    std::string axis = d.get("x", "seconds");
    if (axis != "seconds" && axis != "samples") {
      throw SourceError{line, "x must be seconds or samples, not '" + axis + "'"};
    }
    fs::path file, summary;
    std::string made_by_text;
    if (!table.empty() && fs::exists(src_dir_ / table)) {
      file = src_dir_ / table;
      if (fs::path(table).extension() == ".json") summary = file;
    } else if (d.attributes.count("scene")) {
      fs::path scene = find_scene(d.get("scene"), line);
      if (!studies_) {
        try {
          studies_ = std::make_unique<StudyCache>(opt_.bench, opt_.cache_dir, opt_.time_limit_seconds);
        } catch (const RenderError& e) {
          throw SourceError{line, e.what()};
        }
      }
      CachedStudy st;
      try {
        st = studies_->study(scene, effective(d.get("flags")));
      } catch (const RenderError& e) {
        throw SourceError{line, e.what()};
      } catch (const DirectiveError& e) {
        throw SourceError{line, e.what()};
      }
      if (timed_.emplace(st.key, st.seconds).second && opt_.log) {
        *opt_.log << "website: " << (st.from_cache ? "cached " : "measured ") << st.command << " ("
                  << seconds_text(st.seconds) << ")\n";
      }
      file = st.csv;
      summary = st.json;
      made_by_text = "<code>" + xml_escape(st.command) + "</code> <span class=\"time\">" +
                     seconds_text(st.seconds) + "</span>";
      if (table.empty()) table = "convergence-" + scene.stem().string() + ".csv";
    } else if (!table.empty()) {
      throw SourceError{line, "plot: no table '" + table + "' beside the write-up (give scene=FILE "
                              "to have bench measure one)"};
    } else {
      throw SourceError{line, "plot needs csv=FILE or json=FILE, or scene=FILE to measure one"};
    }
    std::string svg;
    try {
      auto rows = read_convergence_table(file);
      svg = convergence_svg(rows, axis == "seconds" ? PlotAxis::seconds : PlotAxis::samples,
                            d.get("title", "Error against " + axis), fs::path(table).filename().string());
    } catch (const PlotError& e) {
      throw SourceError{line, std::string("plot: ") + e.what()};
    }
    fs::path dir = make_dir(opt_.out_dir / "plots");
    std::string stem = fs::path(table).stem().string();
    std::string name = stem + "-" + axis + ".svg";
    std::ofstream(dir / name) << svg;
    publish(dir / name);
    std::string data = publish_as(file, "plots", stem + file.extension().string());
    PageImage img;
    img.src = "plots/" + name;
    img.size = svg_size(svg);
    img.alt = d.get("title", "convergence plot");
    std::string caption = caption_html(d.get("caption"), line);
    std::string words = caption;
    if (!made_by_text.empty()) words += (words.empty() ? "" : "<br>") + made_by_text;
    words += std::string(words.empty() ? "" : " ") + "<a href=\"" + xml_escape(data) +
             "\">the table</a>";
    return "<figure class=\"plot\">" + image_html(img) + time_to_target_html(summary) +
           "<figcaption>" + words + "</figcaption></figure>";
  }

  static PixelSize svg_size(const std::string& svg) {
    std::smatch m;
    static const std::regex size("<svg[^>]*\\swidth=\"([0-9.]+)\"[^>]*\\sheight=\"([0-9.]+)\"");
    if (!std::regex_search(svg, m, size)) return {0, 0};
    return {int(std::stod(m[1])), int(std::stod(m[2]))};
  }

  /// bench's summary of a study: how long each strategy took to reach one error, as a table.
  static std::string time_to_target_html(const fs::path& json_file) {
    if (json_file.empty()) return "";
    auto j = nlohmann::json::parse(std::ifstream(json_file), nullptr, false);
    if (!j.is_object() || !j.contains("time_to_target") || !j["time_to_target"].is_array()) return "";
    double target = j.value("/target/relMSE"_json_pointer, 0.0);
    std::string rows;
    for (const auto& t : j["time_to_target"]) {
      if (!t.is_object()) continue;
      std::string when = "not reached in the study";
      if (t.value("beyond_reach", false)) {
        when = "too far off to tell";
      } else if (t.contains("seconds") && t["seconds"].is_number()) {
        when = (t.value("extrapolated", false) ? "≈ " : "") + seconds_text(t["seconds"].get<double>());
      }
      std::string ratio = "";
      if (t.contains("ratio_to_light") && t["ratio_to_light"].is_number()) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "× %.2f", t["ratio_to_light"].get<double>());
        ratio = buf;
      }
      rows += "<tr><th scope=\"row\">" + xml_escape(t.value("strategy", "?")) +
              "</th><td class=\"number\">" + when + "</td><td class=\"number\">" + ratio +
              "</td></tr>";
    }
    if (rows.empty()) return "";
    char head[128];
    std::snprintf(head, sizeof head, "time to a relative MSE of %.3g", target);
    return "<table class=\"time-to-target\"><thead><tr><th>strategy</th><th>" + std::string(head) +
           "</th><th>against light sampling</th></tr></thead><tbody>" + rows + "</tbody></table>";
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

  std::string draft_banner() const {
    if (!opt_.quick) return "";
    return "<p class=\"draft\">Draft (<code>website build --quick</code>): every render at half "
           "its width and height, with the samples the captions name. Build without "
           "<code>--quick</code> for the page you hand in.</p>\n";
  }

  /// What rendering the page costs: each distinct render and study, timed when it was made.
  std::string render_time_note() const {
    if (timed_.empty()) return "";
    return "\n<p class=\"render-time\">The " + std::to_string(timed_.size()) +
           " renders and measurements on this page took " + seconds_text(report_.render_seconds) +
           " in all, each timed when it was made" + (opt_.quick ? " (draft sizes)" : "") +
           ".</p>\n";
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
    std::string scripts;
    if (uses_slider_) {
      fs::copy_file(opt_.web_dir / "assets" / "compare.js", opt_.out_dir / "compare.js",
                    fs::copy_options::overwrite_existing);
      publish(opt_.out_dir / "compare.js");
      scripts = "<script src=\"compare.js\" defer></script>";
    }
    replace_all(page, "{{title}}", xml_escape(title_));
    replace_all(page, "{{stylesheets}}", css_links);
    replace_all(page, "{{scripts}}", scripts);
    replace_all(page, "{{body}}", body);
    fs::copy_file(opt_.web_dir / "assets" / "style.css", opt_.out_dir / "style.css",
                  fs::copy_options::overwrite_existing);
    publish(opt_.out_dir / "style.css");
    std::ofstream(opt_.out_dir / "index.html") << page;
    publish(opt_.out_dir / "index.html");
  }

  /// The gap between cells of a grid, in CSS pixels (style.css says the same).
  static constexpr int kGap = 12;

  const BuildOptions& opt_;
  fs::path src_dir_;
  BuildReport report_;
  ProtectedMarkdown protected_;
  std::vector<MathSpan> math_;
  std::unique_ptr<RenderCache> cache_;
  std::unique_ptr<StudyCache> studies_;
  std::map<std::string, double> timed_;  ///< each distinct render and study, by key: its seconds
  bool uses_slider_ = false;
  std::string title_, katex_css_;
  bool have_title_ = false;
};

}  // namespace

BuildReport build_site(const BuildOptions& options) { return SiteBuilder(options).run(); }

}  // namespace pt::web
