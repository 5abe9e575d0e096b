#include "parix/backend.hpp"

#include <cstdlib>
#include <stdexcept>

#include "parix/mpi_runtime.hpp"

namespace gcsim::parix {

namespace {

RunResult run_on_simulated_machine(const RunOptions& options, const Program& program) {
  return run_simulated(options.simulation, program);
}

// On the root rank the whole result comes back and the caller reports it; the other ranks have
// sent their part to the root and end here, quietly, so that one mpirun prints one report.
RunResult run_on_mpi_ranks(const RunOptions& options, const Program& program) {
  MpiRunResult r = run_mpi(options.simulation, program);
  if (!r.root) std::exit(0);  // MPI is finalized at exit (mpi_initialize)
  return std::move(r.result);
}

}  // namespace

// A new backend is one more entry here (and its files beside simulated_runtime.cpp).
const std::vector<Backend>& backends() {
  static const std::vector<Backend> all{
      {"simulated", "the discrete-event model of the machine (simulated time)", &run_on_simulated_machine},
      {"mpi", "real processes, one per MPI rank, under mpirun -np N (wall-clock time)", &run_on_mpi_ranks},
  };
  return all;
}

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const Backend& b : backends()) names.emplace_back(b.name);
  return names;
}

RunResult run(const RunOptions& options, const Program& program) {
  for (const Backend& b : backends())
    if (b.name == options.backend) return b.run(options, program);
  std::string known;
  for (const Backend& b : backends()) known += (known.empty() ? "" : ", ") + std::string(b.name);
  throw std::invalid_argument("unknown backend '" + options.backend + "': expected one of " + known);
}

}  // namespace gcsim::parix
