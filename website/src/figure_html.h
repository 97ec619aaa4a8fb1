// The HTML of the write-up's figures: an image at its own size (with the region a zoomed crop
// shows outlined on it), a two-image slider, the sample-rate image's colour key and the small
// texts under renders. Pure text in, text out, so the page's markup is tested on its own.
#pragma once

#include <optional>
#include <string>

#include "website/src/page_images.h"

namespace pt::web {

/// An image as the page shows it: its path relative to index.html, its size in pixels (written
/// into the tag, and the width it is shown at), the words for a reader who cannot see it, and
/// the pixels a zoomed crop of it shows, outlined on it.
struct PageImage {
  std::string src;
  PixelSize size;
  std::string alt;
  std::optional<PixelRect> marked;
};

/// <img> with its width and height, wrapped with an outline of `marked` when there is one.
std::string image_html(const PageImage& image, const std::string& css_class = "");

/// A slider between two images of the same size: `over` is shown left of the split, `under`
/// right of it; the range input (and a pointer on the picture) moves the split. Works as a
/// still half-and-half picture where scripts do not run.
std::string slider_html(const PageImage& over, const std::string& over_label,
                        const PageImage& under, const std::string& under_label);

/// The colour key of a sample-rate image whose colours run from blue (no samples) through
/// green to red (`max_samples`, the render's -s), as wide as the image.
std::string rate_key_html(int max_samples, int width);

/// "0.42 s", "12.3 s", "2 min 05 s".
std::string seconds_text(double seconds);

/// "1,234,567".
std::string thousands(long long n);

}  // namespace pt::web
