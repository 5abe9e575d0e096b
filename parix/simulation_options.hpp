#pragma once
// What a run on the simulated machine is given: the machine, the trace, where each processor runs
// and what a node's memory limit does. Part of the API (RunOptions holds it, and a real backend
// reads its machine and trace too); the simulated backend itself is parix/sim/simulated_runtime.hpp.
#include <vector>

#include "machine/machine_config.hpp"
#include "machine/node_memory.hpp"
#include "machine/trace.hpp"

namespace gcsim::parix {

struct SimulationOptions {
  // The machine the program runs on: one processor per node (machine::with_nodes cuts a machine
  // down to N nodes), connected by the config's network model.
  machine::MachineConfig config;
  machine::TraceOptions trace;         // no path: no trace
  // Processor i runs on node placement[i]; empty: processor i on node i. A permutation of the
  // nodes, e.g. machine::map_onto(...).node_of for a virtual topology (parix/virtual_topology.hpp).
  std::vector<int> placement;
  // A node's memory exceeded: the run fails at once (enforce) or goes on and reports its peak (warn).
  machine::MemoryLimit memory_limit = machine::MemoryLimit::enforce;
};

}  // namespace gcsim::parix
