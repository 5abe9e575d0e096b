#include "apps/raytrace/tile_sample.hpp"

#include <algorithm>

namespace gcsim::raytrace {

std::vector<int> sampled_tiles(const Tiling& tiling, int stride, int run) {
  stride = std::max(stride, 1), run = std::max(run, 1);
  std::vector<int> tiles;
  for (int y = 0; y < tiling.tiles_y(); ++y)
    for (int x = 0; x < tiling.tiles_x(); ++x)
      if ((x / run + y) % stride == stride / 2 % stride) tiles.push_back(y * tiling.tiles_x() + x);
  return tiles;
}

}  // namespace gcsim::raytrace
