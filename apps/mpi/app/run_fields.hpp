#pragma once
// What an MPI run's JSON says beyond every run's figures (simulated, wall, nodes, model, config,
// provenance with the command line): the machine, the program and its arguments, the ranks, the
// options that change its times, the trace files; `gcsim report` titles its page with them.
#include <string>

#include <nlohmann/json.hpp>

#include "apps/mpi/app/mpirun_options.hpp"

namespace gcsim::mpi_layer::app {

nlohmann::json run_fields(const MpirunOptions& o, const std::string& machine_name);

}  // namespace gcsim::mpi_layer::app
