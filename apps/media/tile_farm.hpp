#pragma once
// Dynamic tile distribution on parix (a tile farm): node 0 is the master; it hands out tiles one at a
// time to the workers as their results come back (each result is also the request for more) and
// renders tiles itself on a thread on its second CPU. Radiance sampling takes M = b S_h samples, so
// tile costs are uneven and a static split would leave nodes idle. Which node renders a tile depends
// on simulated time only, so the assignment is deterministic; the pixels do not depend on it at all.
#include <cstdint>
#include <functional>
#include <span>

#include "parix/processor.hpp"

namespace gcsim::media {

struct TileFarm {
  int tiles = 0;
  // Renders one tile on the calling processor (charging its compute) and returns its record.
  std::function<parix::Bytes(parix::Processor&, int tile)> render;
  // Node 0 only: takes one returned record into the result.
  std::function<void(parix::Processor&, int tile, std::span<const std::byte> record)> assemble;
};

struct TileFarmStats {
  std::uint64_t assignments = 0;   // tile messages sent by the master
  std::uint64_t result_bytes = 0;  // tile records received by the master
};

// Every processor calls it; returns on node 0 when every tile is assembled. Statistics on node 0.
TileFarmStats run_tile_farm(parix::Processor& p, const TileFarm& farm);

}  // namespace gcsim::media
