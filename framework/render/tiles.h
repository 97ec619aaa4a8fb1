// Not needed for the assignment.
// Splitting an image (or a -p cell of it) into the tiles threads render one at a time.
#pragma once

#include <vector>

namespace pt {

/// A rectangle of pixels [x0, x1) × [y0, y1), rows counted from the top.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  long area() const { return long(width()) * long(height()); }
};

/// Covers `region` with tiles of at most tile_size × tile_size pixels, each pixel in exactly one
/// tile, row by row from the top-left; edge tiles are smaller. An empty region gives no tiles.
std::vector<PixelRect> split_into_tiles(const PixelRect& region, int tile_size);

}  // namespace pt
