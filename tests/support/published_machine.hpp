#pragma once
// The published GC-PowerPlus cut to N nodes, as the parallel tests of every application run it.
#include "machine/machine_config.hpp"
#include "parix/simulated_runtime.hpp"

namespace gcsim::test_support {

inline parix::SimulationOptions published_machine(int nodes) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::default_machine_config(), nodes);
  return o;
}

}  // namespace gcsim::test_support
