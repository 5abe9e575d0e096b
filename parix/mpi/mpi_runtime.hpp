#pragma once
// Runs an SPMD program on a real cluster: one virtual processor per MPI rank (OpenMPI from
// Debian), started by `mpirun -np N gcsim ... --backend mpi`. The same application source as on
// the simulated GC: links are point-to-point channels (one MPI tag per link, so a link keeps
// sending order), compute() does no charging (the work itself took the time) but still counts
// operations, spawn() starts a host thread (MPI_THREAD_MULTIPLE), and times are wall-clock.
//
// Each rank runs its processor; at the end every rank's counters and trace records travel to
// rank 0, which returns the whole RunResult and writes the trace (the same three formats as a
// simulated run, with real timestamps). The other ranks return a RunResult with `root == false`:
// callers print and write files on the root only.
#include <functional>

#include "parix/processor.hpp"
#include "parix/run_result.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix {

// Initializes MPI on first use (MPI_THREAD_MULTIPLE) and finalizes it at exit.
void mpi_initialize();
int mpi_rank();
int mpi_size();

struct MpiRunResult {
  RunResult result;  // complete on the root; the local processor's part elsewhere
  bool root = false;
};

// The machine's node count (options.config.nodes) must equal the number of ranks; the machine file
// supplies the name and the node memory that use_memory() checks against.
MpiRunResult run_mpi(const SimulationOptions& options, const std::function<void(Processor&)>& program);

}  // namespace gcsim::parix
