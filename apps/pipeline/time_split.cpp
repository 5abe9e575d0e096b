#include "apps/pipeline/time_split.hpp"

#include <fmt/format.h>

namespace gcsim::pipeline {

std::string time_split(const parix::RunResult& r) {
  const double busy = r.mean_compute_seconds(), communicating = r.mean_communicating_seconds(),
               waiting = r.mean_waiting_seconds();
  std::string line = fmt::format("busy {:.6f} s, communicating {:.6f} s, waiting {:.6f} s: means per processor", busy,
                                 communicating, waiting);
  // Threads a processor spawns (a tile server beside node 0's own rendering) run at the same time
  // as it, and their time is its time.
  if (busy + communicating + waiting > r.simulated_seconds() * (1 + 1e-9))
    line += ", with the time of the threads each spawned, so they add up to more than the run took";
  return line;
}

}  // namespace gcsim::pipeline
