#include "apps/raytrace/tile_prefetch.hpp"

#include <stdexcept>

namespace gcsim::raytrace {

TilePrefetch::TilePrefetch(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Tiling& tiling,
                           std::vector<int> order, int workers)
    : tiling_(tiling) {
  if (!usable(settings.algorithm)) throw std::invalid_argument("TilePrefetch: B1's beams depend on the rays traced before");
  std::vector<apps::WorkAhead<RenderedTile>::Compute> computes;
  for (int i = 0; i < workers; ++i) {
    renderers_.push_back(std::make_unique<TileRenderer>(scene, bvh, settings));
    computes.push_back([this, r = renderers_.back().get()](int tile) { return render(tile, *r); });
  }
  ahead_ = std::make_unique<apps::WorkAhead<RenderedTile>>(tiling.count(), std::move(order), std::move(computes));
}

RenderedTile TilePrefetch::render(int tile, TileRenderer& r) const {
  if (tile < 0 || tile >= tiling_.count()) throw std::out_of_range("TilePrefetch: no such tile");
  const Tiling::Rect rect = tiling_.rect(tile);
  const std::size_t pixels = std::size_t(rect.pixels());
  RenderedTile out{std::vector<glm::vec3>(pixels), std::vector<std::int32_t>(pixels), {}, {}};
  r.render_tile(rect.x0, rect.y0, rect.x1, rect.y1, out.colors, out.prims, out.counters, &out.row_counters);
  return out;
}

RenderedTile TilePrefetch::take(int tile, TileRenderer& own) {
  return ahead_->take(tile, [&](int t) { return render(t, own); });
}

}  // namespace gcsim::raytrace
