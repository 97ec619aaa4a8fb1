// The film a render accumulates into: running statistics per pixel, read out as image or estimate.
#pragma once

#include <vector>

#include "framework/image/image.h"
#include "framework/image/render_estimate.h"
#include "framework/render/pixel_stats.h"

namespace pt {

/// One PixelStats per pixel of a width × height image (row-major, top row first). Tiles write
/// disjoint pixels, so threads share a Film without locks. Pixels no sample reached (outside a
/// -p cell) read as black with count 0.
class Film {
 public:
  Film(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  PixelStats& at(int x, int y) { return pixels_[index(x, y)]; }
  const PixelStats& at(int x, int y) const { return pixels_[index(x, y)]; }

  /// The mean of each pixel's samples.
  Image mean_image() const;
  /// Mean, variance of one sample and sample count per pixel: what the graders compare.
  RenderEstimate estimate() const;
  /// Samples taken over the whole film (decision samples included: PixelStats::samples_taken).
  long total_samples() const;

 private:
  size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }
  int width_, height_;
  std::vector<PixelStats> pixels_;
};

}  // namespace pt
