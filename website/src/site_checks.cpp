#include "website/src/site_checks.h"

#include <sys/stat.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "framework/text/text_file.h"

namespace fs = std::filesystem;

namespace pt::web {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

/// The file's text, or empty when it cannot be read (a permission problem is reported on its own).
std::string read_text(const fs::path& p) {
  try {
    return read_text_file(p);
  } catch (const std::runtime_error&) {
    return {};
  }
}

/// Line numbers of offsets into one text, computed once.
class LineIndex {
 public:
  explicit LineIndex(const std::string& text) {
    for (size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') starts_.push_back(i + 1);
    }
  }
  int line_of(size_t offset) const {
    return static_cast<int>(std::upper_bound(starts_.begin(), starts_.end(), offset) -
                            starts_.begin());
  }

 private:
  std::vector<size_t> starts_{0};
};

/// Reads a quoted or bare value starting at `i`; leaves `i` after it.
std::string read_value(const std::string& text, size_t& i, const std::string& bare_stops) {
  if (i < text.size() && (text[i] == '"' || text[i] == '\'')) {
    char quote = text[i++];
    size_t end = text.find(quote, i);
    if (end == std::string::npos) end = text.size();
    std::string v = text.substr(i, end - i);
    i = std::min(end + 1, text.size());
    return v;
  }
  size_t start = i;
  while (i < text.size() && bare_stops.find(text[i]) == std::string::npos &&
         !std::isspace(static_cast<unsigned char>(text[i]))) {
    ++i;
  }
  return text.substr(start, i - start);
}

void skip_space(const std::string& text, size_t& i) {
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
}

/// The CSS url() values of `text`, with lines from `index`.
void collect_css_urls(const std::string& text, const LineIndex& index,
                      std::vector<FoundReference>& out) {
  std::string low = lower(text);
  for (size_t pos = low.find("url("); pos != std::string::npos; pos = low.find("url(", pos + 4)) {
    if (pos > 0 && (std::isalnum(static_cast<unsigned char>(low[pos - 1])) || low[pos - 1] == '-'))
      continue;
    size_t i = pos + 4;
    skip_space(text, i);
    FoundReference ref;
    ref.line = index.line_of(pos);
    ref.target = read_value(text, i, ")");
    while (!ref.target.empty() && std::isspace(static_cast<unsigned char>(ref.target.back())))
      ref.target.pop_back();
    ref.embedded = true;
    out.push_back(ref);
  }
}

/// HTML comments blanked out, newlines kept, so that offsets and lines stay right.
std::string without_comments(std::string html) {
  for (size_t start = html.find("<!--"); start != std::string::npos;
       start = html.find("<!--", start)) {
    size_t end = html.find("-->", start + 4);
    end = end == std::string::npos ? html.size() : end + 3;
    for (size_t i = start; i < end; ++i) {
      if (html[i] != '\n') html[i] = ' ';
    }
    start = end;
  }
  return html;
}

std::string percent_decode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

/// The URL scheme of a reference ("http", "file", "c" for C:\...), or "" for a plain path.
std::string scheme_of(const std::string& target) {
  size_t colon = target.find(':');
  if (colon == std::string::npos || colon == 0) return "";
  for (size_t i = 0; i < colon; ++i) {
    char c = target[i];
    bool ok = std::isalpha(static_cast<unsigned char>(c)) ||
              (i > 0 && (std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' ||
                         c == '.'));
    if (!ok) return "";
  }
  return lower(target.substr(0, colon));
}

/// Image formats a browser shows; anything else in an <img> is a broken picture.
const std::set<std::string>& browser_image_extensions() {
  static const std::set<std::string> kinds = {".png", ".jpg", ".jpeg", ".gif",
                                              ".webp", ".svg", ".bmp", ".ico", ".avif"};
  return kinds;
}

}  // namespace

std::string Problem::to_string() const {
  std::string s = file.string();
  if (line > 0) s += ":" + std::to_string(line);
  return s + ": " + message;
}

std::vector<FoundReference> find_html_references(const std::string& raw_html) {
  std::string html = without_comments(raw_html);
  std::string low = lower(html);
  LineIndex index(html);
  std::vector<FoundReference> out;
  for (const char* name : {"src", "href", "poster"}) {
    std::string attr = name;
    for (size_t pos = low.find(attr); pos != std::string::npos; pos = low.find(attr, pos + 1)) {
      // An attribute name stands after whitespace inside a tag, and is followed by '='.
      if (pos == 0 || !std::isspace(static_cast<unsigned char>(low[pos - 1]))) continue;
      size_t tag_open = low.rfind('<', pos), tag_close = low.rfind('>', pos);
      if (tag_open == std::string::npos ||
          (tag_close != std::string::npos && tag_close > tag_open)) {
        continue;
      }
      size_t i = pos + attr.size();
      skip_space(html, i);
      if (i >= html.size() || html[i] != '=') continue;
      ++i;
      skip_space(html, i);
      FoundReference ref;
      ref.line = index.line_of(pos);
      ref.target = read_value(html, i, ">");
      std::string tag = low.substr(tag_open + 1, 4);
      // <a href> is followed by the reader; everything else is loaded with the page.
      ref.embedded = !(attr == "href" && (tag.rfind("a ", 0) == 0 || tag.rfind("a\n", 0) == 0 ||
                                          tag.rfind("a\t", 0) == 0 || tag.rfind("area", 0) == 0));
      out.push_back(ref);
    }
  }
  collect_css_urls(html, index, out);
  std::sort(out.begin(), out.end(),
            [](const FoundReference& a, const FoundReference& b) { return a.line < b.line; });
  return out;
}

std::vector<FoundReference> find_css_references(const std::string& css) {
  std::vector<FoundReference> out;
  collect_css_urls(css, LineIndex(css), out);
  return out;
}

std::optional<std::string> content_mismatch(const fs::path& file) {
  std::string ext = lower(file.extension().string());
  static const std::map<std::string, std::string> raster = {
      {".png", "png"}, {".jpg", "jpeg"}, {".jpeg", "jpeg"}, {".gif", "gif"},
      {".webp", "webp"}, {".bmp", "bmp"}, {".tif", "tiff"}, {".tiff", "tiff"},
      {".exr", "openexr"}, {".hdr", "hdr"}};
  std::string head = read_text(file).substr(0, 1024);
  if (auto it = raster.find(ext); it != raster.end()) {
    // OpenImageIO tries the reader of the extension first and then every other one, so the
    // format it reports is what the bytes really are.
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
      (void)OIIO::geterror();
      return "is named " + ext + " but is not an image of any format";
    }
    std::string real = in->format_name();
    if (real != it->second) {
      return "is named " + ext + " but is really a " + (real == "jpeg" ? "JPEG" : real) +
             " image: rename it or convert it";
    }
    return std::nullopt;
  }
  auto starts = [&](const std::string& magic) { return head.rfind(magic, 0) == 0; };
  if (ext == ".svg" && lower(head).find("<svg") == std::string::npos) {
    return "is named .svg but holds no <svg> element";
  }
  if (ext == ".woff2" && !starts("wOF2")) return "is named .woff2 but is not a WOFF2 font";
  if (ext == ".woff" && !starts("wOFF")) return "is named .woff but is not a WOFF font";
  if (ext == ".ttf" && !starts(std::string("\0\1\0\0", 4)) && !starts("true")) {
    return "is named .ttf but is not a TrueType font";
  }
  if (ext == ".pdf" && !starts("%PDF")) return "is named .pdf but is not a PDF";
  return std::nullopt;
}

std::optional<std::string> permission_problem(const fs::path& root, const fs::path& file) {
  struct stat st {};
  if (stat(file.c_str(), &st) != 0) return std::nullopt;  // missing files are reported apart
  if (!(st.st_mode & S_IROTH)) {
    return "is not readable by others (a web server cannot send it): chmod o+r";
  }
  // Every folder below the root must let others through (the root is checked once, apart).
  fs::path dir = root;
  for (const fs::path& part : file.lexically_relative(root).parent_path()) {
    dir /= part;
    const fs::path& d = dir;
    if (stat(d.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH)) {
      return "lies in folder " + d.lexically_relative(root).generic_string() + " that others cannot enter: chmod o+rx";
    }
  }
  return std::nullopt;
}

std::optional<fs::path> check_reference(const fs::path& root, const fs::path& base,
                                        const FoundReference& ref, const fs::path& where,
                                        std::vector<Problem>& problems) {
  auto report = [&](const std::string& message) {
    problems.push_back({where, ref.line, "'" + ref.target + "' " + message});
  };
  std::string target = ref.target;
  target = target.substr(0, std::min(target.find('#'), target.find('?')));
  if (target.empty()) return std::nullopt;  // a link within the page
  std::string scheme = scheme_of(target);
  if (scheme.size() == 1) {
    report("is an absolute Windows path: use a path relative to the page");
    return std::nullopt;
  }
  if (scheme == "file") {
    report("is an absolute file:// URL, which works only on your machine: use a relative path");
    return std::nullopt;
  }
  if (!scheme.empty()) {
    bool web = scheme == "http" || scheme == "https";
    if (ref.embedded && web) {
      report("is loaded from the web: copy it into the folder and use a relative path");
    } else if (ref.embedded && scheme != "data") {
      report("uses the URL scheme '" + scheme + ":', which a page cannot load from the folder");
    }
    return std::nullopt;  // a link out (https, mailto) is the reader's to follow
  }
  if (target[0] == '/' || target[0] == '\\' || target[0] == '~') {
    report("is an absolute path, which works only on your machine: use a path relative to the page");
    return std::nullopt;
  }
  if (target.find('\\') != std::string::npos) {
    report("uses backslashes: web paths separate folders with '/'");
    return std::nullopt;
  }
  fs::path rel = (base.lexically_relative(root) / percent_decode(target)).lexically_normal();
  if (rel.empty() || *rel.begin() == "..") {
    report("points outside the folder, so it is missing from the submission");
    return std::nullopt;
  }
  // Walk down from the root comparing names exactly: on a case-insensitive disk (macOS,
  // Windows) a wrong capitalisation works at home and breaks on the course's server.
  fs::path at = root;
  for (const fs::path& part : rel) {
    if (part == ".") continue;
    std::string want = part.string();
    std::error_code ec;
    if (!fs::is_directory(at, ec)) {
      report("is missing: " + at.lexically_relative(root).string() + " is not a folder");
      return std::nullopt;
    }
    std::optional<std::string> exact, near;
    for (const fs::directory_entry& e : fs::directory_iterator(at, ec)) {
      std::string name = e.path().filename().string();
      if (name == want) exact = name;
      else if (lower(name) == lower(want)) near = name;
    }
    if (!exact && near) {
      fs::path shown = (at / *near).lexically_relative(root);
      report("has the wrong capitalisation: the file is '" + shown.generic_string() +
             "' (names are case-sensitive on a web server)");
      return std::nullopt;
    }
    if (!exact) {
      report("is missing: no file '" + rel.generic_string() + "' in the folder");
      return std::nullopt;
    }
    at /= want;
  }
  std::error_code ec;
  fs::path real = fs::weakly_canonical(at, ec);
  fs::path real_root = fs::weakly_canonical(root, ec);
  auto rr = real.lexically_relative(real_root);
  if (rr.empty() || *rr.begin() == "..") {
    report("is a link to a file outside the folder, which the submission will not hold");
    return std::nullopt;
  }
  if (fs::is_directory(at)) {
    if (!fs::exists(at / "index.html")) report("is a folder without an index.html");
    return std::nullopt;
  }
  if (ref.embedded && browser_image_extensions().count(lower(at.extension().string())) == 0 &&
      lower(at.extension().string()) != ".css" && lower(at.extension().string()) != ".js" &&
      lower(at.extension().string()).find("woff") == std::string::npos &&
      lower(at.extension().string()) != ".ttf") {
    report("has a type (" + at.extension().string() + ") that browsers do not show: save it as PNG");
  }
  if (auto why = content_mismatch(at)) report(*why);
  if (auto why = permission_problem(root, at)) report(*why);
  return at;
}

std::vector<Problem> check_folder(const fs::path& root) {
  std::vector<Problem> problems;
  fs::path index = root / "index.html";
  if (!fs::is_regular_file(index)) {
    problems.push_back({root, 0, "has no index.html (the page the course's server opens)"});
    return problems;
  }
  struct stat st {};
  if (stat(root.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH)) {
    problems.push_back({root, 0, "is a folder that others cannot enter: chmod o+rx"});
  }
  if (auto why = permission_problem(root, index)) problems.push_back({index, 0, *why});
  std::vector<fs::path> todo = {index};
  std::set<fs::path> seen = {index};
  while (!todo.empty()) {
    fs::path page = todo.back();
    todo.pop_back();
    std::string ext = lower(page.extension().string());
    std::string text = read_text(page);
    auto refs = ext == ".css" ? find_css_references(text) : find_html_references(text);
    for (const FoundReference& ref : refs) {
      auto hit = check_reference(root, page.parent_path(), ref, page, problems);
      if (!hit) continue;
      std::string hext = lower(hit->extension().string());
      if ((hext == ".html" || hext == ".htm" || hext == ".css") && seen.insert(*hit).second) {
        todo.push_back(*hit);
      }
    }
  }
  return problems;
}

}  // namespace pt::web
