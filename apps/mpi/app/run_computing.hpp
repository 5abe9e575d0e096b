#pragma once
// A run's computation settings (gcsim mpirun --compute, --host-speed): the mode, the node's time per
// flop, the host speed (timed at construction under measured, so the figure is the run's from its
// start) and the tables its ranks share. `gcsim mpirun` and each point of `gcsim sweep mpi` make one.
#include <nlohmann/json.hpp>

#include "apps/mpi/app/mpirun_options.hpp"
#include "apps/mpi/runtime/compute_meter.hpp"
#include "apps/mpi/runtime/compute_samples.hpp"
#include "apps/mpi/runtime/host_speed.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::mpi_layer::app {

struct RunComputing {
  HostSpeed host_speed;
  SampleSites global_samples;
  ComputeTotals totals;
  ComputeSettings settings;

  // Exit 2 (pipeline::ExitStatus) when the host speed needs a node rate the machine file lacks.
  RunComputing(const MpirunOptions& o, const machine::MachineConfig& config);
  RunComputing(const RunComputing&) = delete;  // settings point into this object
  RunComputing& operator=(const RunComputing&) = delete;

  nlohmann::json to_json() const;
  void print() const;  // the run summary's "compute" line
};

}  // namespace gcsim::mpi_layer::app
