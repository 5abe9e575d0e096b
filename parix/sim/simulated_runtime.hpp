#pragma once
// Runs an SPMD program on the simulated machine: each virtual processor is a fiber (Boost.Context) whose
// blocking calls become events on the discrete-event kernel.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/machine_config.hpp"
#include "machine/node_memory.hpp"
#include "machine/trace.hpp"
#include "parix/processor.hpp"
#include "parix/run_result.hpp"

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

// Every processor blocked and no event pending. what() is the report naming each blocked
// processor, its call and its peer.
class DeadlockError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs program on every virtual processor; returns when all have returned.
// Throws DeadlockError on deadlock, rethrows the first exception an application threw.
RunResult run_simulated(const SimulationOptions& options, const std::function<void(Processor&)>& program);

}  // namespace gcsim::parix
