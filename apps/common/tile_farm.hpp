#pragma once
// The master–worker tile farm both tile renderers run on parix (the ray tracer's dynamic
// distribution, the media renderer's farm). Node 0 is the master: it hands out runs of tiles from a
// pool, `prefetch` runs ahead to each worker so none idles for a round trip, and renders from the
// same pool itself on a thread on its second CPU. A worker renders each run it is given and sends
// the run's records back in one message, which is also its request for more. Which node renders a
// tile depends on simulated time only, so the assignment is deterministic.
//
// What varies between the renderers is a parameter, so each keeps its own message sizes and order:
// the pool (single tiles, or guided runs), the assignment's encoding, when workers are told to stop,
// the tile work and the record encoding.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "parix/processor.hpp"

namespace gcsim::apps {

// Consecutive tiles handed out in one assignment.
struct TileRun {
  std::int32_t first = 0;
  std::int32_t count = 1;
};

// How an assignment travels: one int32 tile (-1: stop), or a run as int32 first and count
// (first -1: stop).
enum class AssignmentFormat { single_tile, tile_run };

// When a worker gets its stop: as soon as it asks and the pool is dry, or only once every result
// is in.
enum class StopTiming { when_dry, at_end };

struct TileFarm {
  int tag = 0;       // of the links between node 0 and the workers
  int prefetch = 2;  // runs assigned to a worker ahead of its results
  AssignmentFormat format = AssignmentFormat::single_tile;
  StopTiming stops = StopTiming::at_end;
  // Node 0 (the master and its own thread): takes the next run from the pool; nullopt once the pool
  // is dry, and on every call after. single_tile takes runs of one tile only.
  std::function<std::optional<TileRun>()> next_run{};
  // Renders one tile on the calling processor (charging its compute) and returns its record; a
  // run's records travel concatenated.
  std::function<parix::Bytes(parix::Processor&, int tile)> render{};
  // Node 0: takes in records, a worker's message (a whole run) or one tile node 0 rendered itself.
  std::function<void(parix::Processor&, std::span<const std::byte> records)> assemble{};
};

struct TileFarmStats {
  std::uint64_t assignments = 0;   // runs the master sent to workers (stops not counted)
  std::uint64_t result_bytes = 0;  // bytes of the workers' result messages
};

// Every processor calls it; returns on node 0 once every tile is assembled. Statistics on node 0.
TileFarmStats run_tile_farm(parix::Processor& p, const TileFarm& farm);

// Node 0 opens a link to every other node at once (one thread each), so the set-up times overlap
// instead of adding up; element 0 stays unopened.
std::vector<parix::Link> connect_root_to_all(parix::Processor& p, int tag);

}  // namespace gcsim::apps
