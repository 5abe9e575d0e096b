#pragma once
// Host threads for one simulated render (--host-threads T). A tile's pixels, hit ids and counts
// are a function of the tile alone, except the cost of its row's two planes (2.2.1), which a node
// pays only when the tile starts a new row for it. So T - 1 worker threads render the tiles ahead,
// in the order they will be handed out, each noting its row's cost apart; a node takes a tile
// (rendering it itself if no worker has started it, helping with the next ones while a worker
// finishes it) and adds the row's cost when the row is new to it, exactly as its own tracer would.
// Images, simulated times and traces are the same for every T (tests); only the wall time changes.
//
// The kernel and the nodes' fibers stay on one host thread. Not for B1, whose beams grow with the
// rays a node traced (ray_classification.hpp). One per simulated run; under MPI every rank renders
// its own tiles.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "apps/common/work_ahead.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/raytrace/tile_renderer.hpp"

namespace gcsim::raytrace {

struct RenderedTile {
  std::vector<glm::vec3> colors;
  std::vector<std::int32_t> prims;
  TraceCounters counters;      // without the row's planes
  TraceCounters row_counters;  // the row's planes
};

class TilePrefetch {
 public:
  // order: the tiles in the order nodes are expected to render them.
  TilePrefetch(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Tiling& tiling,
               std::vector<int> order, int workers);

  // Tile `tile`, rendered ahead or now with `own` (the taking node's renderer); each tile once.
  RenderedTile take(int tile, TileRenderer& own);
  std::int64_t tiles_by_workers() const { return ahead_->by_workers(); }

  static bool usable(Algorithm a) { return a != Algorithm::B1; }

 private:
  RenderedTile render(int tile, TileRenderer& r) const;

  Tiling tiling_;
  std::vector<std::unique_ptr<TileRenderer>> renderers_;  // one per worker, made on the simulation's thread
  std::unique_ptr<apps::WorkAhead<RenderedTile>> ahead_;  // last: its workers stop before the renderers go
};

}  // namespace gcsim::raytrace
