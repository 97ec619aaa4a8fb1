// Not needed for the assignment: the definitions of framework/render/tiles.h.
#include "framework/render/tiles.h"

#include <algorithm>
#include <stdexcept>

namespace pt {

std::vector<PixelRect> split_into_tiles(const PixelRect& region, int tile_size) {
  if (tile_size < 1) throw std::invalid_argument("split_into_tiles: tile size must be at least 1");
  std::vector<PixelRect> tiles;
  for (int y = region.y0; y < region.y1; y += tile_size)
    for (int x = region.x0; x < region.x1; x += tile_size)
      tiles.push_back({x, y, std::min(x + tile_size, region.x1), std::min(y + tile_size, region.y1)});
  return tiles;
}

}  // namespace pt
