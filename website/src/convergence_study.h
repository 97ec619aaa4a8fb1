// The run-time-against-error table of a write-up made on the spot: `bench convergence` runs
// as a child with a small budget, and its table is kept in the render cache, keyed like a render.
#pragma once

#include <filesystem>
#include <string>

#include "website/src/render_cache.h"

namespace pt::web {

/// One finished study: bench's table (CSV), its summary (JSON: the target error and each
/// strategy's time to it) and how it was made.
struct CachedStudy {
  std::filesystem::path csv;
  std::filesystem::path json;
  double seconds = 0;    ///< wall-clock time of the bench run that made it
  std::string command;   ///< as a reader would type it
  std::string key;
  bool from_cache = false;
};

/// Runs `bench convergence` once per distinct (scene, flags, binary) and remembers the result.
class StudyCache {
 public:
  /// Throws RenderError when there is no bench executable at `bench`.
  StudyCache(std::filesystem::path bench, std::filesystem::path cache_dir, int time_limit_seconds);

  /// The study of `scene` with bench's convergence options `flags` (without --out, which the
  /// cache adds). Throws RenderError with bench's message when the study fails.
  CachedStudy study(const std::filesystem::path& scene, const std::string& flags);

 private:
  std::filesystem::path bench_;
  std::filesystem::path cache_dir_;
  int time_limit_seconds_;
  std::string binary_hash_;
};

}  // namespace pt::web
