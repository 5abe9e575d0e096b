#pragma once
// The media renderer on the simulated GC (parix): photons traced in parallel (photon i on its own
// random stream, so any split gives the same photons), the photon maps replicated by all-gather, the
// SH grids built voxel-slice by voxel-slice and all-gathered, image tiles handed out dynamically by
// node 0 (apps/common/tile_farm.hpp). Compute is charged from counted operations ([ops] media_* in the machine file).
#include <cstdint>
#include <memory>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/work_ahead.hpp"
#include "apps/media/media_render.hpp"
#include "parix/run_result.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::media {

struct ParallelMediaResult {
  parix::RunResult run;
  apps::Image image;
  RenderCounters counters;            // summed over the nodes
  std::uint64_t photon_bytes = 0;     // one node's photon contribution to the all-gather (node 0)
  std::uint64_t photon_bytes_all = 0; // the whole replicated photon maps, per node
  std::uint64_t grid_bytes_all = 0;   // the whole SH grids (inside + outside), per node
  std::size_t outside_photons = 0, inside_photons = 0;
  glm::ivec3 outside_dims{0}, inside_dims{0};
  std::size_t tiles = 0;                // kTileSize² tiles of the image
  std::uint64_t tile_messages = 0;      // assignments the master sent
  std::uint64_t tile_result_bytes = 0;  // tile records the master received
  std::int64_t tiles_by_workers = 0;    // render_media_parallel with host threads: tiles rendered ahead
};

inline constexpr int kTileSize = 16;

// One tile's pixels (luminance) and what rendering them counted: a function of the tile alone.
struct PixelTile {
  std::vector<float> pixels;
  RenderCounters counters;
};

// --host-threads: `workers` threads render the tiles ahead (apps/common/work_ahead.hpp) from node
// 0's photon maps and grids, which every node holds alike; node 0 starts them when its own are
// built and stops them when the image is assembled. Nodes charge each tile's counts as they take it.
struct MediaHostThreads {
  int workers = 0;
  std::unique_ptr<apps::WorkAhead<PixelTile>> ahead;  // while node 0 farms out the tiles
  std::int64_t tiles_by_workers = 0;                  // after the run
  // Every node gathers the same photons and grid voxels, so the first to build a region's photon
  // map (with its k-d tree) and grid lends them to the others, which compare what they gathered
  // with them piece by piece instead of copying it (host time only: building the tree and copying
  // the packets are not charged, so simulated times do not change).
  struct SharedRegion {
    std::shared_ptr<const PhotonMap> map;
    std::shared_ptr<const RadianceGrid> grid;
  };
  SharedRegion outside, inside;
};

// The SPMD program: every processor runs it; result.image (sized by the caller) and the byte and
// photon figures are filled by processor 0, per_node[id] (one slot per processor, never sent) by
// each processor for the host-side sum of counters after the run.
// host: null, or the run's host threads (one object for all processors).
void media_program(parix::Processor& p, const MediaScene& scene, const MarchSettings& settings, std::uint64_t seed,
                   ParallelMediaResult& result, std::vector<RenderCounters>& per_node, MediaHostThreads* host = nullptr);

ParallelMediaResult render_media_parallel(const MediaScene& scene, const MarchSettings& settings, std::uint64_t seed,
                                          const parix::SimulationOptions& sim, int host_threads = 1);

}  // namespace gcsim::media
