#include "website/src/render_cache.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <limits>

#include "framework/image/image.h"
#include "grader/process/child_process.h"
#include "framework/text/text_file.h"
#include "website/src/directive.h"

namespace fs = std::filesystem;

namespace pt::web {

ContentHash& ContentHash::add(const std::string& bytes) {
  for (unsigned char c : bytes) {
    state_ ^= c;
    state_ *= 1099511628211ull;
  }
  // The length separates fields, so ("ab","c") and ("a","bc") differ.
  std::string len = "|" + std::to_string(bytes.size()) + "|";
  for (unsigned char c : len) {
    state_ ^= c;
    state_ *= 1099511628211ull;
  }
  return *this;
}

ContentHash& ContentHash::add_file(const fs::path& file) {
  try {
    return add(read_text_file(file));
  } catch (const std::runtime_error& e) {
    throw RenderError(e.what());
  }
}

std::string ContentHash::hex() const {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(state_));
  return buf;
}

std::optional<RenderSummary> parse_render_summary(const std::string& output) {
  // "render: 320x240[ (cell ...)], 64 spp[ on average], 31.39 s, ..."
  static const std::regex line(
      R"(render: (\d+)x(\d+)(?: \(cell[^)]*\))?, ([0-9.]+) spp(?: on average)?, ([0-9.]+) s\b[^\n]*)");
  std::smatch m;
  if (!std::regex_search(output, m, line)) return std::nullopt;
  RenderSummary s;
  s.width = std::stoi(m[1]);
  s.height = std::stoi(m[2]);
  s.samples_per_pixel = std::stod(m[3]);
  s.seconds = std::stod(m[4]);
  s.line = m[0];
  return s;
}

double child_time_limit(int seconds) {
  return seconds > 0 ? double(seconds) : std::numeric_limits<double>::infinity();
}

std::string child_failure_message(const ChildResult& run, int seconds, const std::string& command,
                                  const std::string& nothing) {
  if (run.timed_out)
    return "`" + command + "` took longer than the time limit of " + std::to_string(seconds) +
           " s and was stopped (website build --time-limit SECONDS changes it)";
  const std::string why = tail_lines(run.errors + "\n" + run.output, 6);
  return "`" + command + "` failed" +
         (run.exit_code > 0 ? " with exit code " + std::to_string(run.exit_code)
          : run.ok()        ? std::string()
                            : " (it " + run.describe() + ")") +
         (why.empty() ? ", and wrote " + nothing : ":\n" + why);
}

RenderCache::RenderCache(fs::path pathtracer, fs::path cache_dir, int time_limit_seconds)
    : pathtracer_(std::move(pathtracer)),
      cache_dir_(std::move(cache_dir)),
      time_limit_seconds_(time_limit_seconds) {
  if (!fs::is_regular_file(pathtracer_)) {
    throw RenderError("no pathtracer executable at " + pathtracer_.string() +
                      " (build it with: cmake --build build --target pathtracer, or name it "
                      "with --pathtracer)");
  }
  binary_hash_ = ContentHash().add_file(pathtracer_).hex();
}

const std::string& RenderCache::scene_hash(const fs::path& scene) {
  auto it = scene_hashes_.find(scene);
  if (it == scene_hashes_.end()) {
    it = scene_hashes_.emplace(scene, ContentHash().add_file(scene).hex()).first;
  }
  return it->second;
}

std::string RenderCache::key(const fs::path& scene, const std::string& flags, bool linear) {
  ContentHash h;
  h.add(scene_hash(scene)).add(scene.filename().string()).add(flags).add(binary_hash_);
  if (linear) h.add("exr");  // keys of PNG renders stay what they were
  return h.hex();
}

bool RenderCache::load(const fs::path& entry, CachedRender& result) const {
  if (!fs::exists(entry / "meta.json") || !fs::exists(entry / "render.png")) return false;
  result.image = entry / "render.png";
  result.linear = fs::exists(entry / "render.exr") ? entry / "render.exr" : fs::path();
  result.extras.clear();
  for (const fs::directory_entry& e : fs::directory_iterator(entry)) {
    std::string ext = e.path().extension().string();
    if (e.path() != result.image && (ext == ".png" || ext == ".jpg")) {
      result.extras.push_back(e.path());
    }
  }
  std::sort(result.extras.begin(), result.extras.end());
  auto meta = nlohmann::json::parse(std::ifstream(entry / "meta.json"), nullptr, false);
  result.seconds = meta.is_object() ? meta.value("seconds", 0.0) : 0.0;
  result.summary = parse_render_summary(meta.is_object() ? meta.value("output", "") : "");
  return true;
}

CachedRender RenderCache::render(const fs::path& scene, const std::string& flags, bool linear) {
  if (!fs::is_regular_file(scene)) throw RenderError("scene file " + scene.string() + " not found");
  std::vector<std::string> args = split_flags(flags);
  for (const std::string& a : args) {
    if (a == "-f") throw RenderError("flags must not contain -f: the write-up names the image");
  }
  CachedRender result;
  result.command = "pathtracer " + flags + (flags.empty() ? "" : " ") + scene.filename().string();
  // A linear render of the same flags holds the same picture: take it when there is one.
  for (bool exr : {true, false}) {
    if (!exr && linear) continue;
    result.key = key(scene, flags, exr);
    if (load(cache_dir_ / result.key, result)) {
      result.from_cache = true;
      return result;
    }
  }
  result.key = key(scene, flags, linear);
  fs::path entry = cache_dir_ / result.key;
  // Render into a scratch folder and rename it at the end, so that an interrupted run never
  // leaves a half-written entry behind that a later run would take for finished.
  fs::path scratch = cache_dir_ / (result.key + ".partial");
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  const fs::path written = scratch / (linear ? "render.exr" : "render.png");
  std::vector<std::string> argv = {pathtracer_.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"-f", written.string(), scene.string()});
  auto start = std::chrono::steady_clock::now();
  const ChildResult run = run_child(argv, child_time_limit(time_limit_seconds_), {}, 1 << 20,
                                    ChildStreams::separate);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!run.ok() || !fs::exists(written)) {
    fs::remove_all(scratch);
    throw RenderError(child_failure_message(run, time_limit_seconds_, result.command, "no image"));
  }
  if (linear) {
    try {
      write_image((scratch / "render.png").string(), read_image(written.string()));
    } catch (const ImageError& e) {
      fs::remove_all(scratch);
      throw RenderError("`" + result.command + "` wrote an EXR that cannot be read: " + e.what());
    }
  }
  std::ofstream(scratch / "meta.json")
      << nlohmann::json{{"seconds", seconds}, {"command", result.command}, {"output", run.output}}
             .dump(2);
  fs::remove_all(entry);
  fs::rename(scratch, entry);
  load(entry, result);
  return result;
}

}  // namespace pt::web
