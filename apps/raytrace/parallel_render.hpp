#pragma once
// The image rendered by the nodes of the simulated GC: subregions (tiles) are distributed over
// the processors, each renders its tiles with its own TileRenderer, built by the processor itself
// (every node holds the scene and the tree), charges the counted operations to its CPU, and the
// pixels travel to node 0, which assembles the image.
//   static       each node takes one contiguous block of tiles (scanline order)
//   interleaved  tile i goes to node i mod N
//   dynamic      node 0 is a master handing out runs of tiles on request (guided
//                self-scheduling: long runs first, single tiles at the end); every worker keeps
//                two requests outstanding so it does not idle during the round trip, and a
//                worker thread on node 0's second CPU takes runs from the same pool (the tile
//                farm of apps/common/tile_farm.hpp, shared with the media renderer)
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/raytrace/render_settings.hpp"
#include "parix/run_result.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::raytrace {

class PreparedChildPairs;

class TilePrefetch;

class Scene;

enum class Distribution { static_blocks, interleaved, dynamic };
// The longest run of consecutive tiles the dynamic distribution hands out: long enough to share row
// planes, short enough to balance.
inline constexpr int kRunTiles = 4;
std::optional<Distribution> parse_distribution(std::string_view s);  // static, interleaved, dynamic
std::string_view name_of(Distribution d);

// Primary-hit ids of one tile, as its node found them.
struct TilePrims {
  int tile = -1;
  std::vector<std::int32_t> prims;
};

// What a parallel render produces. Only node 0 writes the image (from the pixels it received).
// per_node, tiles_per_node and node_prims are check data: node i writes only element i, never
// reads another's, and nothing in them is sent (sending the hit ids with the pixels would change
// the message sizes, and so the simulated times); ParallelRenderJob::finish merges them on the host
// after the run. A distributed backend gathers these slots after the run, outside measured time.
struct ParallelRender {
  parix::RunResult run;
  apps::Image image;                       // as assembled on node 0
  std::vector<std::int32_t> prim_ids;      // primary hits, merged from node_prims after the run
  TraceCounters counters;                  // all nodes
  std::vector<TraceCounters> per_node;
  std::vector<int> tiles_per_node;
  std::vector<std::vector<TilePrims>> node_prims;  // per node; emptied by finish()
  // Host-side progress (a line on a terminal, what an interrupted run reached): the tiles any node
  // of this host rendered so far, of the image's; on_tile is called after each. Nothing of it is
  // simulated or sent.
  std::function<void(int done, int total)> on_tile;
  int tiles_rendered = 0, tiles_total = 0;
  std::int64_t tiles_by_workers = 0;  // render_parallel with host threads: tiles a worker rendered ahead
};

// The 8-bit RGB image node 0 assembles from the tiles: what a render holds of it in node memory.
inline std::int64_t assembled_image_bytes(int width, int height) { return std::int64_t(width) * height * 3; }

// The per-processor program of a parallel render, run by whichever backend the caller chooses.
class ParallelRenderJob {
 public:
  ParallelRenderJob(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Distribution distribution);
  ParallelRender new_result(int nodes) const;  // image and per-node slots sized for `nodes`
  // prefetch: tiles rendered ahead on host threads (make_prefetch), or null.
  void program(parix::Processor& p, ParallelRender& out, TilePrefetch* prefetch = nullptr) const;
  // For one simulated run on `nodes` with `host_threads` (--host-threads): null if 1, or for B1.
  std::unique_ptr<TilePrefetch> make_prefetch(int nodes, int host_threads) const;
  void finish(ParallelRender& out) const;      // sums the counters, merges the hit ids
  // Renders only a sample of the tiles (dynamic distribution only): one run of kRunTiles in
  // `stride`, on diagonals (tile_sample.hpp), handed out in runs as long as the whole image's at
  // that point, so that a node's tiles share their row planes as often as in the whole image. A
  // sample of the view whose cost `gcsim plan` scales up; other tiles stay black.
  void sample_tiles(int stride);
  // Traces one pixel row in `stride` of every tile it renders and charges the tile's counts scaled
  // to all its rows: each tile's cost estimated, the schedule's imbalance kept.
  void sample_pixel_rows(int stride);
  int tiles_rendered_per_run() const;          // the tiles one run renders (all, or the sample's)

  // Node memory, declared before the host allocates it: every node's scene and tree, the 8-bit
  // image node 0 assembles, the buffers of one tile being rendered.
  std::int64_t scene_bytes() const;
  std::int64_t image_bytes() const { return assembled_image_bytes(settings_.width, settings_.height); }
  std::int64_t tile_bytes() const;

 private:
  const Scene& scene_;
  const Bvh& bvh_;
  RenderSettings settings_;
  Distribution distribution_;
  std::vector<int> order_;  // the tiles the dynamic distribution hands out, in this order (every tile, or a sample)
  double schedule_scale_ = 1.0;  // image tiles per tile of order_ when runs are sized as the whole image's
  int pixel_row_stride_ = 1;     // sample_pixel_rows'
  // The row filter's child pairs of bvh_, made once for every node's tracer (each its own took as
  // much memory again as the run on 1024 nodes of TEAPOTS); null when the algorithm filters no rows.
  std::shared_ptr<const PreparedChildPairs> pairs_;
};

// Runs the job on the simulated machine (for tests and callers without a pipeline), with
// host_threads - 1 workers rendering tiles ahead (make_prefetch).
ParallelRender render_parallel(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Distribution distribution,
                               const parix::SimulationOptions& options, int host_threads = 1);

}  // namespace gcsim::raytrace
