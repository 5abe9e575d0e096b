#pragma once
// A4's halving of a subregion into pixel regions (section 2.2.3), worked out once per tile shape.
// Which regions a tile reaches depends on its rays (a uniform region is filled in, not halved),
// but the halving itself does not: the regions of each level, whose half each one is, and the
// corner pixels each level is the first to need are fixed by the tile's width and height.
#include <vector>

namespace gcsim::raytrace {

struct RegionRect {
  int x0, y0, x1, y1;  // corner pixels, inclusive
};

struct PixelOffset {
  int x, y;
};

struct RegionLevel {
  std::vector<RegionRect> rects;  // from the tile's corner pixel (0, 0)
  std::vector<int> parent;        // the previous level's rect each one halves (-1 on level 0)
  // The corners of this level's rects that no earlier level's rect has, in 4 x 2 pixel blocks
  // (pairs of rows, four columns a block, row by row inside one): neighbours next to each other
  // for the packets.
  std::vector<PixelOffset> new_corners;
};

class RegionSchedule {
 public:
  RegionSchedule(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<RegionLevel>& levels() const { return levels_; }

 private:
  int width_, height_;
  std::vector<RegionLevel> levels_;
};

}  // namespace gcsim::raytrace
