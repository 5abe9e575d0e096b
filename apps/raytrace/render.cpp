#include "apps/raytrace/render.hpp"

#include <algorithm>
#include <chrono>

#include "apps/raytrace/tile_renderer.hpp"

namespace gcsim::raytrace {

Tiling::Rect Tiling::rect(int index) const {
  const int tx = index % tiles_x(), ty = index / tiles_x();
  return {tx * tile, ty * tile, std::min(width, (tx + 1) * tile), std::min(height, (ty + 1) * tile)};
}

RenderOutput render_image(const Scene& scene, const Bvh& bvh, const RenderSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  RenderOutput out;
  out.image = apps::Image(settings.width, settings.height);
  out.prim_ids.assign(std::size_t(settings.width) * settings.height, -1);
  TileRenderer renderer(scene, bvh, settings);
  const Tiling tiling{settings.width, settings.height, settings.tile};
  std::vector<glm::vec3> colors;
  std::vector<std::int32_t> prims;
  for (int i = 0; i < tiling.count(); ++i) {
    const auto r = tiling.rect(i);
    colors.resize(r.pixels());
    prims.resize(r.pixels());
    renderer.render_tile(r.x0, r.y0, r.x1, r.y1, colors, prims, out.counters);
    const int w = r.x1 - r.x0;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const std::size_t k = std::size_t(y - r.y0) * w + (x - r.x0);
        out.image.at(x, y) = colors[k];
        out.prim_ids[std::size_t(y) * settings.width + x] = prims[k];
      }
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace gcsim::raytrace
