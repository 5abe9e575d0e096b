// The tiles a sample of the view renders (gcsim plan's view and media samples): one run of 4 in k,
// on diagonals, so that every row and every column of tiles is sampled alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "apps/raytrace/parallel_render.hpp"
#include "apps/raytrace/tile_sample.hpp"

namespace gcsim::raytrace {
namespace {

TEST(TileSample, StrideOneIsEveryTile) {
  const Tiling tiling{64, 48, 8};
  const std::vector<int> tiles = sampled_tiles(tiling, 1, kRunTiles);
  ASSERT_EQ(int(tiles.size()), tiling.count());
  for (int t = 0; t < tiling.count(); ++t) EXPECT_EQ(tiles[std::size_t(t)], t);
}

// 8 x 6 tiles, one run of 4 in 3: the picked run moves one back each row (row 2's would be a third
// run of 4, past the row's 8 tiles).
TEST(TileSample, OneRunOfFourInKOnDiagonals) {
  const Tiling tiling{64, 48, 8};
  const std::vector<int> expected = {4, 5, 6, 7, 8, 9, 10, 11, 28, 29, 30, 31, 32, 33, 34, 35};
  EXPECT_EQ(sampled_tiles(tiling, 3, kRunTiles), expected);
}

// A 40 x 30 tiling, one run in 4: a quarter of the tiles, every row of tiles holds whole runs of 4,
// every column is sampled in a quarter of the rows (to one row), and single tiles (run 1) too.
TEST(TileSample, EveryRowAndColumnIsSampledAlike) {
  const Tiling tiling{320, 240, 8};
  for (int run : {1, kRunTiles}) {
    SCOPED_TRACE(run);
    const std::vector<int> tiles = sampled_tiles(tiling, 4, run);
    EXPECT_EQ(int(tiles.size()), tiling.count() / 4);
    EXPECT_TRUE(std::is_sorted(tiles.begin(), tiles.end()));
    std::map<int, int> per_row, per_column;
    for (int t : tiles) ++per_row[t / tiling.tiles_x()], ++per_column[t % tiling.tiles_x()];
    for (const auto& [row, n] : per_row) EXPECT_EQ(n % run, 0) << row;
    for (int x = 0; x < tiling.tiles_x(); ++x) EXPECT_NEAR(per_column[x], tiling.tiles_y() / 4.0, 1.0) << x;
  }
}

}  // namespace
}  // namespace gcsim::raytrace
