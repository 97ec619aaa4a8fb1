// Renders made on the spot for the write-up, by the pathtracer executable, kept in a cache
// keyed by what decides the picture: the scene file's bytes, the flags and the pathtracer binary.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "grader/process/child_process.h"

namespace pt::web {

/// A 64-bit FNV-1a hash, as 16 hex digits: a cache key, not a security measure.
class ContentHash {
 public:
  ContentHash& add(const std::string& bytes);
  ContentHash& add_file(const std::filesystem::path& file);
  std::string hex() const;

 private:
  uint64_t state_ = 14695981039346656037ull;
};

/// A render the pathtracer could not make; the message holds its error output.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the pathtracer says about a finished render on its summary line
/// ("render: 320x240, 300.3 spp on average, 57.65 s, ..."): the render alone, without loading
/// the scene or building the BVH, which is what a comparison of traversal speed needs.
struct RenderSummary {
  int width = 0, height = 0;
  double samples_per_pixel = 0;  ///< the mean, for an adaptive render
  double seconds = 0;
  std::string line;              ///< the line as printed
};

/// Reads the summary line out of the pathtracer's standard output, or nothing if it has none.
std::optional<RenderSummary> parse_render_summary(const std::string& output);

/// One finished render: its image and the other images the pathtracer wrote beside it (the
/// sample-rate image of adaptive sampling), how long it took and how it was made.
struct CachedRender {
  std::filesystem::path image;      ///< always a PNG
  std::filesystem::path linear;     ///< the linear-float EXR, when one was asked for
  std::vector<std::filesystem::path> extras;
  double seconds = 0;      ///< wall-clock time of the pathtracer run that made it
  std::optional<RenderSummary> summary;
  std::string command;     ///< the command line, as a reader would type it
  std::string key;         ///< the cache key
  bool from_cache = false;
};

/// Runs the pathtracer once per distinct (scene, flags, binary) and remembers the result.
class RenderCache {
 public:
  /// `time_limit_seconds` > 0 stops a render that runs longer (a hung renderer must not hang
  /// the build); 0 waits for ever.
  RenderCache(std::filesystem::path pathtracer, std::filesystem::path cache_dir,
              int time_limit_seconds = 0);

  /// The render of `scene` with `flags` (without -f, which the cache adds). With `linear`, the
  /// pathtracer writes an EXR (for arithmetic on the values) and the PNG is encoded from it as
  /// the pathtracer encodes its own; a later plain request with the same flags reuses it.
  /// Throws RenderError.
  CachedRender render(const std::filesystem::path& scene, const std::string& flags,
                      bool linear = false);

 private:
  std::string key(const std::filesystem::path& scene, const std::string& flags, bool linear);
  bool load(const std::filesystem::path& entry, CachedRender& result) const;
  /// The hash of a scene file's bytes, read once per build (a write-up renders the same large
  /// mesh many times).
  const std::string& scene_hash(const std::filesystem::path& scene);

  std::filesystem::path pathtracer_;
  std::filesystem::path cache_dir_;
  int time_limit_seconds_ = 0;
  std::string binary_hash_;
  std::map<std::filesystem::path, std::string> scene_hashes_;
};

/// The limit to give the child-process runner for a time limit of `seconds`: none for 0.
double child_time_limit(int seconds);

/// Why `command`, run with time limit `seconds`, gave no result, in words: stopped at the limit,
/// its exit code or what ended it, and the last lines it printed (or that it wrote `nothing`,
/// e.g. "no image", when it printed none). Renders and the convergence study say it alike.
std::string child_failure_message(const ChildResult& run, int seconds, const std::string& command,
                                  const std::string& nothing);

}  // namespace pt::web
