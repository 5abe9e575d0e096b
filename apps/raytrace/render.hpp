#pragma once
// A whole image on the host, tile by tile in scanline order (the sequential renderer the
// parallel one is checked against).
#include <cstdint>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/raytrace/render_settings.hpp"

namespace gcsim::raytrace {

class Scene;

// Subregions of m x m pixels in scanline order (the last row and column may be smaller).
struct Tiling {
  int width, height, tile;
  int tiles_x() const { return (width + tile - 1) / tile; }
  int tiles_y() const { return (height + tile - 1) / tile; }
  int count() const { return tiles_x() * tiles_y(); }
  struct Rect { int x0, y0, x1, y1; int pixels() const { return (x1 - x0) * (y1 - y0); } };
  Rect rect(int index) const;
};

struct RenderOutput {
  apps::Image image;
  std::vector<std::int32_t> prim_ids;  // primary hit per pixel, -1 for background
  TraceCounters counters;
  double wall_seconds = 0;
};

RenderOutput render_image(const Scene& scene, const Bvh& bvh, const RenderSettings& settings);

}  // namespace gcsim::raytrace
