// A4's halving worked out once per tile shape must be the halving itself: every region inside its
// parent, a level's regions disjoint and covering the tile while no region is filled, each corner
// first needed exactly once, in the 4 x 2 block order of the packets.
#include <algorithm>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "apps/raytrace/region_schedule.hpp"

namespace gcsim::raytrace {
namespace {

bool inside(const RegionRect& q, const RegionRect& parent) {
  return q.x0 >= parent.x0 && q.x1 <= parent.x1 && q.y0 >= parent.y0 && q.y1 <= parent.y1;
}

TEST(RegionSchedule, HalvesCoverEveryPixelAndAddEachCornerOnce) {
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{8, 8}, {1, 1}, {2, 2}, {3, 1}, {7, 5}, {16, 3}, {64, 64}}) {
    const RegionSchedule s(w, h);
    std::vector<int> corner_seen(std::size_t(w) * h, 0);
    for (std::size_t l = 0; l < s.levels().size(); ++l) {
      const RegionLevel& level = s.levels()[l];
      ASSERT_FALSE(level.rects.empty());
      ASSERT_EQ(level.parent.size(), level.rects.size());
      std::vector<int> covered(std::size_t(w) * h, 0);
      for (std::size_t i = 0; i < level.rects.size(); ++i) {
        const RegionRect& q = level.rects[i];
        ASSERT_LE(q.x0, q.x1);
        ASSERT_LE(q.y0, q.y1);
        if (l == 0) {
          EXPECT_EQ(level.parent[i], -1);
        } else {
          ASSERT_TRUE(inside(q, s.levels()[l - 1].rects[std::size_t(level.parent[i])])) << w << "x" << h;
        }
        for (int y = q.y0; y <= q.y1; ++y)
          for (int x = q.x0; x <= q.x1; ++x) ++covered[std::size_t(y) * w + x];
      }
      // Regions that are all corners are not halved, so a later level covers less of the tile.
      for (int c : covered) ASSERT_LE(c, 1) << w << "x" << h << " level " << l;
      if (l == 0) {
        EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), w * h);
      }
      for (const PixelOffset& p : level.new_corners) ++corner_seen[std::size_t(p.y) * w + p.x];
      for (std::size_t k = 1; k < level.new_corners.size(); ++k) {
        const PixelOffset a = level.new_corners[k - 1], b = level.new_corners[k];
        EXPECT_LT(std::tuple(a.y / 2, a.x / 4, a.y % 2, a.x), std::tuple(b.y / 2, b.x / 4, b.y % 2, b.x));
      }
    }
    // Halving down to regions of at most 2 x 2 makes every pixel a corner, each added once.
    for (int c : corner_seen) ASSERT_EQ(c, 1) << w << "x" << h;
  }
}

TEST(RegionSchedule, AnEightByEightTileTakesFiveLevels) {
  const RegionSchedule s(8, 8);
  ASSERT_EQ(s.levels().size(), 5u);
  const std::size_t regions[] = {1, 2, 4, 8, 16};
  const std::size_t corners[] = {4, 4, 8, 16, 32};  // 64 pixels in all
  for (std::size_t l = 0; l < 5; ++l) {
    EXPECT_EQ(s.levels()[l].rects.size(), regions[l]);
    EXPECT_EQ(s.levels()[l].new_corners.size(), corners[l]) << "level " << l;
  }
}

}  // namespace
}  // namespace gcsim::raytrace
