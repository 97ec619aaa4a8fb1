// The reference image of a convergence study: rendered once at a high sample count, cached on
// disk under a key made from the scene file's content and the render settings, reused after.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

#include "framework/image/image.h"
#include "framework/render/render_settings.h"
#include "framework/stats/block_ttest.h"

namespace pt {

/// A reference and where it came from.
struct Reference {
  RenderEstimate estimate;       ///< mean, variance of one sample, samples per pixel
  Image image;                   ///< the mean, as an image
  std::string key;               ///< 16 hex digits: scene content and settings
  std::filesystem::path exr;     ///< the cached estimate (R, G, B, varR, varG, varB, n)
  std::filesystem::path manifest;///< JSON beside it: how it was made
  bool reused = false;           ///< read from the cache rather than rendered now
  double seconds = 0.0;          ///< wall time of its render (when it was made)
  /// The relative MSE the reference's own noise adds to every measured error, estimated from its
  /// per-pixel variance: mean of var / (n · (ref² + ε)). Errors near it say the reference is
  /// too noisy to measure them.
  double noise_rel_mse = 0.0;
};

/// What a render of the reference returns: its estimate and its wall time.
struct ReferenceRender {
  RenderEstimate estimate;
  double seconds = 0.0;
};

/// Renders the reference with the given settings.
using ReferenceRenderer = std::function<ReferenceRender(const RenderSettings& settings)>;

/// The cache key of a reference of `scene_path` rendered with `settings`: a fingerprint of the
/// scene file's bytes (and of the environment map's, if any) and of every setting that changes
/// the image. Throws std::runtime_error naming the file when it cannot be read.
std::string reference_key(const std::string& scene_path, const RenderSettings& settings);

/// Reads the reference cached in `dir` under the key of (scene_path, settings), or, when there
/// is none, its manifest does not match, or `fresh` is set, renders it with `render` and writes
/// dir/reference-KEY.exr and dir/reference-KEY.json (creating dir). Says which on `log`.
Reference load_or_make_reference(const std::string& scene_path, const RenderSettings& settings,
                                 const std::filesystem::path& dir, const ReferenceRenderer& render,
                                 bool fresh, std::ostream& log);

}  // namespace pt
