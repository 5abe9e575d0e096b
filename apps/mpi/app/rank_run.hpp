#pragma once
// One run of an MPI program on the simulated machine, one rank per node: what `gcsim mpirun` does
// and what `gcsim sweep mpi` does once per node count and machine, so that both give the same
// simulated times for the same program, machine and node count.
#include <string>
#include <vector>

#include "apps/mpi/app/mpirun_options.hpp"
#include "apps/mpi/app/program_copies.hpp"
#include "apps/mpi/runtime/compute_meter.hpp"
#include "parix/backend.hpp"
#include "parix/run_result.hpp"

namespace gcsim::mpi_layer::app {

struct RankRun {
  parix::RunResult result;
  std::vector<int> statuses;  // each rank's exit status
  int failed_rank = -1;       // the first rank whose status is not 0, or -1
  std::string failed_stderr;  // that rank's stderr when the output was kept silent
};

// Runs o's program on o.np ranks with `run` (machine, nodes, trace), charging computation as
// `computing` says. The ranks' output is printed
// in rank order at the end, or kept (`silent`). MPI_Abort ends it with pipeline::ExitStatus after
// saying so; parix::host::Interrupted and the runtime's errors go on up. at_end: what becomes of
// the program's copies after the run (program_copies.hpp).
RankRun run_ranks(const MpirunOptions& o, const parix::RunOptions& run, const ComputeSettings& computing, bool silent,
                  CopiesAtEnd at_end);

}  // namespace gcsim::mpi_layer::app
