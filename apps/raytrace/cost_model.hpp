#pragma once
// Simulated CPU time of counted operations on one processor of a machine (the [ops] table of the
// machine file: cycles per operation, and the clock).
#include "apps/raytrace/counters.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::raytrace {

machine::SimTime single_cpu_time(const TraceCounters& counters, const machine::MachineConfig& config);

}  // namespace gcsim::raytrace
