#include "website/src/render_cache.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "framework/process/child_process.h"
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

RenderCache::RenderCache(fs::path pathtracer, fs::path cache_dir)
    : pathtracer_(std::move(pathtracer)), cache_dir_(std::move(cache_dir)) {
  if (!fs::is_regular_file(pathtracer_)) {
    throw RenderError("no pathtracer executable at " + pathtracer_.string() +
                      " (build it with: cmake --build build --target pathtracer, or name it "
                      "with --pathtracer)");
  }
  binary_hash_ = ContentHash().add_file(pathtracer_).hex();
}

CachedRender RenderCache::render(const fs::path& scene, const std::string& flags) {
  if (!fs::is_regular_file(scene)) throw RenderError("scene file " + scene.string() + " not found");
  std::vector<std::string> args = split_flags(flags);
  for (const std::string& a : args) {
    if (a == "-f") throw RenderError("flags must not contain -f: the write-up names the image");
  }
  CachedRender result;
  result.key = ContentHash()
                   .add_file(scene)
                   .add(scene.filename().string())
                   .add(flags)
                   .add(binary_hash_)
                   .hex();
  fs::path entry = cache_dir_ / result.key;
  result.command = "pathtracer " + flags + (flags.empty() ? "" : " ") + scene.filename().string();
  auto collect = [&] {
    result.image = entry / "render.png";
    for (const fs::directory_entry& e : fs::directory_iterator(entry)) {
      std::string ext = e.path().extension().string();
      if (e.path() != result.image && (ext == ".png" || ext == ".jpg")) {
        result.extras.push_back(e.path());
      }
    }
    std::sort(result.extras.begin(), result.extras.end());
    auto meta = nlohmann::json::parse(std::ifstream(entry / "meta.json"), nullptr, false);
    result.seconds = meta.is_object() ? meta.value("seconds", 0.0) : 0.0;
  };
  if (fs::exists(entry / "meta.json") && fs::exists(entry / "render.png")) {
    result.from_cache = true;
    collect();
    return result;
  }
  // Render into a scratch folder and rename it at the end, so that an interrupted run never
  // leaves a half-written entry behind that a later run would take for finished.
  fs::path scratch = cache_dir_ / (result.key + ".partial");
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  std::vector<std::string> argv = {pathtracer_.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"-f", (scratch / "render.png").string(), scene.string()});
  auto start = std::chrono::steady_clock::now();
  const ChildResult run =
      run_child(argv, kRenderTimeLimitSeconds, {}, 1 << 20, ChildStreams::separate);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!run.ok() || !fs::exists(scratch / "render.png")) {
    std::string why = tail_lines(run.errors + "\n" + run.output, 6);
    fs::remove_all(scratch);
    throw RenderError("`" + result.command + "` failed" +
                      (run.exit_code > 0 ? " with exit code " + std::to_string(run.exit_code)
                       : run.ok()        ? std::string()
                                         : " (it " + run.describe() + ")") +
                      (why.empty() ? ", and wrote no image" : ":\n" + why));
  }
  std::ofstream(scratch / "meta.json")
      << nlohmann::json{{"seconds", seconds}, {"command", result.command}}.dump(2);
  fs::remove_all(entry);
  fs::rename(scratch, entry);
  collect();
  return result;
}

}  // namespace pt::web
