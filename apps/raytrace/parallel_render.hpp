#pragma once
// The image rendered by the nodes of the simulated GC: subregions (tiles) are distributed over
// the processors, each renders its tiles with its own TileRenderer (every node holds the scene
// and the tree), charges the counted operations to its CPU, and the pixels travel to node 0,
// which assembles the image.
//   static       each node takes one contiguous block of tiles (scanline order)
//   interleaved  tile i goes to node i mod N
//   dynamic      node 0 is a master handing out runs of tiles on request (guided
//                self-scheduling: long runs first, single tiles at the end); every worker keeps
//                two requests outstanding so it does not idle during the round trip, and a
//                worker thread on node 0's second CPU takes runs from the same pool
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/raytrace/render_settings.hpp"
#include "parix/run_result.hpp"
#include "parix/simulated_runtime.hpp"

namespace gcsim::raytrace {

class Scene;

enum class Distribution { static_blocks, interleaved, dynamic };
std::optional<Distribution> parse_distribution(std::string_view s);  // static, interleaved, dynamic
std::string_view name_of(Distribution d);

struct ParallelRender {
  parix::RunResult run;
  apps::Image image;                       // as assembled on node 0
  std::vector<std::int32_t> prim_ids;      // primary hits (host-side check, not sent)
  TraceCounters counters;                  // all nodes
  std::vector<TraceCounters> per_node;
  std::vector<int> tiles_per_node;
};

ParallelRender render_parallel(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Distribution distribution,
                               const parix::SimulationOptions& options);

}  // namespace gcsim::raytrace
