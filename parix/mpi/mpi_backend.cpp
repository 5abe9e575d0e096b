// Registers the real-MPI backend: `mpirun -np N gcsim ... --backend mpi`.
#include <cstdlib>
#include <utility>

#include "parix/backend.hpp"
#include "parix/mpi/mpi_runtime.hpp"

namespace gcsim::parix {
namespace {

// On the root rank the whole result comes back and the caller reports it; the other ranks have
// sent their part to the root and end here, quietly, so that one mpirun prints one report.
RunResult run_on_mpi_ranks(const RunOptions& options, const Program& program) {
  MpiRunResult r = run_mpi(options.simulation, program);
  if (!r.root) std::exit(0);  // MPI is finalized at exit (mpi_initialize)
  return std::move(r.result);
}

const BackendRegistrar registrar{
    {"mpi", "real processes, one per MPI rank, under mpirun -np N (wall-clock time)", &run_on_mpi_ranks}};

}  // namespace
}  // namespace gcsim::parix
