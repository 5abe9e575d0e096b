#include "apps/raytrace/region_schedule.hpp"

#include <algorithm>
#include <tuple>

namespace gcsim::raytrace {
namespace {

// Appends the halves of q, along its longer side (the left or upper half takes the middle pixel
// of an odd side), unless every pixel of q is a corner.
void split_region(const RegionRect& q, std::vector<RegionRect>& out) {
  const int w = q.x1 - q.x0 + 1, h = q.y1 - q.y0 + 1;
  if (w <= 2 && h <= 2) return;
  if (w >= h) {
    const int mid = q.x0 + (w - 1) / 2;
    out.push_back({q.x0, q.y0, mid, q.y1});
    out.push_back({mid + 1, q.y0, q.x1, q.y1});
  } else {
    const int mid = q.y0 + (h - 1) / 2;
    out.push_back({q.x0, q.y0, q.x1, mid});
    out.push_back({q.x0, mid + 1, q.x1, q.y1});
  }
}

}  // namespace

RegionSchedule::RegionSchedule(int width, int height) : width_(width), height_(height) {
  std::vector<char> cornered(std::size_t(width) * height, 0);
  RegionLevel level;
  level.rects = {{0, 0, width - 1, height - 1}};
  level.parent = {-1};
  while (!level.rects.empty()) {
    for (const RegionRect& q : level.rects) {
      const PixelOffset corners[4] = {{q.x0, q.y0}, {q.x1, q.y0}, {q.x0, q.y1}, {q.x1, q.y1}};
      for (const PixelOffset& c : corners) {
        char& seen = cornered[std::size_t(c.y) * width + c.x];
        if (!seen) level.new_corners.push_back(c);
        seen = 1;
      }
    }
    auto block_order = [](const PixelOffset& p) { return std::tuple(p.y / 2, p.x / 4, p.y % 2, p.x); };
    std::sort(level.new_corners.begin(), level.new_corners.end(),
              [&](const PixelOffset& a, const PixelOffset& b) { return block_order(a) < block_order(b); });
    RegionLevel next;
    for (std::size_t i = 0; i < level.rects.size(); ++i) {
      split_region(level.rects[i], next.rects);
      next.parent.resize(next.rects.size(), int(i));
    }
    levels_.push_back(std::move(level));
    level = std::move(next);
  }
}

}  // namespace gcsim::raytrace
