#include "website/src/convergence_study.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>

#include "grader/process/child_process.h"
#include "website/src/directive.h"

namespace fs = std::filesystem;

namespace pt::web {

StudyCache::StudyCache(fs::path bench, fs::path cache_dir, int time_limit_seconds)
    : bench_(std::move(bench)), cache_dir_(std::move(cache_dir)),
      time_limit_seconds_(time_limit_seconds) {
  if (!fs::is_regular_file(bench_)) {
    throw RenderError("no bench executable at " + bench_.string() +
                      " to measure error against time (build it with: cmake --build build "
                      "--target bench, or name it with --bench)");
  }
  binary_hash_ = ContentHash().add_file(bench_).hex();
}

CachedStudy StudyCache::study(const fs::path& scene, const std::string& flags) {
  if (!fs::is_regular_file(scene)) throw RenderError("scene file " + scene.string() + " not found");
  std::vector<std::string> args = split_flags(flags);
  for (const std::string& a : args) {
    if (a == "--out") {
      throw RenderError("the study's flags must not contain " + a + ": the write-up names them");
    }
  }
  CachedStudy result;
  result.key = ContentHash()
                   .add("convergence")
                   .add_file(scene)
                   .add(scene.filename().string())
                   .add(flags)
                   .add(binary_hash_)
                   .hex();
  result.command = "bench convergence " + scene.filename().string() +
                   (flags.empty() ? "" : " ") + flags;
  const fs::path entry = cache_dir_ / ("convergence-" + result.key);
  auto finish = [&] {
    result.csv = entry / "convergence.csv";
    result.json = entry / "convergence.json";
    auto meta = nlohmann::json::parse(std::ifstream(entry / "meta.json"), nullptr, false);
    result.seconds = meta.is_object() ? meta.value("seconds", 0.0) : 0.0;
    return result;
  };
  if (fs::exists(entry / "meta.json") && fs::exists(entry / "convergence.csv")) {
    result.from_cache = true;
    return finish();
  }
  const fs::path scratch = cache_dir_ / ("convergence-" + result.key + ".partial");
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  std::vector<std::string> argv = {bench_.string(), "convergence", scene.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"--out", scratch.string()});
  auto start = std::chrono::steady_clock::now();
  const ChildResult run = run_child(argv, child_time_limit(time_limit_seconds_), {}, 1 << 20,
                                    ChildStreams::separate);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!run.ok() || !fs::exists(scratch / "convergence.csv")) {
    fs::remove_all(scratch);
    throw RenderError(child_failure_message(run, time_limit_seconds_, result.command, "no table"));
  }
  std::ofstream(scratch / "meta.json")
      << nlohmann::json{{"seconds", seconds}, {"command", result.command}}.dump(2);
  fs::remove_all(entry);
  fs::rename(scratch, entry);
  return finish();
}

}  // namespace pt::web
