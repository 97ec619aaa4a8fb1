// The pixel work a write-up page needs beyond the renders themselves: an image's size, a
// region cut out and enlarged (a zoomed crop) and the difference of two linear renders.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace pt::web {

/// An image the page cannot use; the message names the file.
class PageImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Width and height in pixels.
struct PixelSize {
  int width = 0, height = 0;
};

/// The size of an image file. Throws PageImageError.
PixelSize image_size(const std::filesystem::path& file);

/// A region of an image as fractions of its width and height (so that it names the same place
/// at any resolution): x, y of its top-left corner, w, h its size, all in [0, 1].
struct Region {
  double x = 0, y = 0, w = 1, h = 1;
};

/// Reads "x y w h" (fractions, inside the image); throws std::invalid_argument saying why not.
Region parse_region(const std::string& text);

/// The pixels `region` covers in an image of `size`: at least one pixel each way.
struct PixelRect {
  int x = 0, y = 0, width = 1, height = 1;
};
PixelRect region_pixels(const Region& region, PixelSize size);

/// Cuts `region` out of `from` and enlarges it by a whole factor (each pixel a square block,
/// so the noise is seen as it is, not smoothed) to about `width` pixels wide, then writes it to
/// `to` (PNG). Returns the size written. Throws PageImageError.
PixelSize write_zoomed_crop(const std::filesystem::path& from, const Region& region, int width,
                            const std::filesystem::path& to);

/// Writes `minuend` − `subtrahend` (linear EXRs of the same size) as a PNG encoded as the
/// pathtracer encodes its renders; a pixel the noise makes negative is black. Throws
/// PageImageError naming the file when they cannot be read or differ in size.
void write_difference(const std::filesystem::path& minuend, const std::filesystem::path& subtrahend,
                      const std::filesystem::path& to);

}  // namespace pt::web
