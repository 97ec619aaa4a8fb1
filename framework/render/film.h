// Not needed for the assignment.
// The film a render accumulates into: running statistics per pixel, read out as image or estimate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "framework/image/image.h"
#include "framework/image/render_estimate.h"
#include "framework/render/pixel_stats.h"

namespace pt {

/// One PixelStats per pixel of a width × height image (row-major, top row first): 56 bytes a
/// pixel (kBytesPerPixel), the mean and the variance in double as Welford's method needs them. Tiles write
/// disjoint pixels, so threads share a Film without locks. Pixels no sample reached (outside a
/// -p cell) read as black with count 0.
class Film {
 public:
  static constexpr size_t kBytesPerPixel = sizeof(PixelStats);

  Film(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  PixelStats& at(int x, int y) { return pixels_[index(x, y)]; }
  const PixelStats& at(int x, int y) const { return pixels_[index(x, y)]; }
  /// Every pixel, row-major, top row first.
  const std::vector<PixelStats>& pixels() const { return pixels_; }

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

/// Writes the film by the path's extension, straight from its statistics: .png as the 8-bit sRGB
/// of each pixel's mean (3 bytes a pixel held while writing), .exr as the estimate's seven float
/// channels (28 bytes a pixel), never an image-sized copy on the way. Throws ImageError.
void write_film(const std::string& path, const Film& film);

/// The most memory a width × height render holds in its film and output buffers at once: the
/// film, plus what write_film holds for `output_path`'s extension, or with `adaptive` the
/// sample-rate PNG written after (its linear image and its bytes, 15 a pixel), if more.
uint64_t film_peak_bytes(int width, int height, const std::string& output_path, bool adaptive);

}  // namespace pt
