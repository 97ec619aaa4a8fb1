#include "website/src/katex_math.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "grader/process/child_process.h"

namespace fs = std::filesystem;

namespace pt::web {

KatexMath::KatexMath(fs::path web_dir) : web_dir_(std::move(web_dir)) {}

std::vector<TypesetMath> KatexMath::typeset(const std::vector<MathSpan>& spans) const {
  if (spans.empty()) return {};
  fs::path script = web_dir_ / "assets" / "render_math.js";
  fs::path katex = web_dir_ / "node_modules" / "katex";
  if (!fs::exists(katex)) {
    throw std::runtime_error("KaTeX is not installed in " + katex.string() +
                             ": run tools/setup.sh (npm ci in website/)");
  }
  nlohmann::json input = nlohmann::json::array();
  for (const MathSpan& s : spans) input.push_back({{"tex", s.tex}, {"display", s.display}});
  std::string tmpl = (fs::temp_directory_path() / "pt-math-XXXXXX").string();
  int fd = mkstemp(tmpl.data());
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for the math");
  close(fd);
  fs::path in_file = tmpl;
  std::ofstream(in_file) << input.dump();
  // Typesetting a page's math takes a second or two; a node that hangs is stopped.
  ChildResult r = run_child({"node", script.string(), in_file.string()}, 300.0, {}, 256 << 20,
                            ChildStreams::separate);
  fs::remove(in_file);
  if (!r.ok()) {
    throw std::runtime_error("typesetting the math with node failed (it " + r.describe() + "): " +
                             tail_lines(r.errors, 5) +
                             (!r.started ? " (is Node.js installed? run tools/setup.sh)" : ""));
  }
  nlohmann::json output = nlohmann::json::parse(r.output, nullptr, false);
  if (!output.is_array() || output.size() != spans.size()) {
    throw std::runtime_error("KaTeX returned an unexpected answer: " + tail_lines(r.output, 3));
  }
  std::vector<TypesetMath> result;
  for (const auto& item : output) {
    result.push_back({item.value("html", ""), item.value("error", "")});
  }
  return result;
}

std::string KatexMath::install_assets(const fs::path& folder) const {
  fs::path dist = web_dir_ / "node_modules" / "katex" / "dist";
  fs::path to = folder / "katex";
  fs::create_directories(to / "fonts");
  fs::copy_file(dist / "katex.min.css", to / "katex.min.css",
                fs::copy_options::overwrite_existing);
  for (const fs::directory_entry& e : fs::directory_iterator(dist / "fonts")) {
    fs::copy_file(e.path(), to / "fonts" / e.path().filename(),
                  fs::copy_options::overwrite_existing);
  }
  return "katex/katex.min.css";
}

}  // namespace pt::web
