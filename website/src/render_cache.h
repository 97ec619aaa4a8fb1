// Renders made on the spot for the write-up, by the pathtracer executable, kept in a cache
// keyed by what decides the picture: the scene file's bytes, the flags and the pathtracer binary.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

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

/// One finished render: its image and the other images the pathtracer wrote beside it (the
/// sample-rate image of adaptive sampling), how long it took and how it was made.
struct CachedRender {
  std::filesystem::path image;
  std::vector<std::filesystem::path> extras;
  double seconds = 0;      ///< wall-clock time of the pathtracer run that made it
  std::string command;     ///< the command line, as a reader would type it
  std::string key;         ///< the cache key
  bool from_cache = false;
};

/// How long one render of a write-up may take before it is stopped and reported: a hung renderer
/// must fail `website build` with a message, not hang it. An hour, as for the graders'
/// references: the write-up's largest renders take minutes.
inline constexpr double kRenderTimeLimitSeconds = 3600.0;

/// Runs the pathtracer once per distinct (scene, flags, binary) and remembers the result.
class RenderCache {
 public:
  RenderCache(std::filesystem::path pathtracer, std::filesystem::path cache_dir);

  /// The render of `scene` with `flags` (without -f, which the cache adds). Throws RenderError.
  CachedRender render(const std::filesystem::path& scene, const std::string& flags);

 private:
  std::filesystem::path pathtracer_;
  std::filesystem::path cache_dir_;
  std::string binary_hash_;
};

}  // namespace pt::web
