#pragma once
// gcsim sweep mpi PROGRAM [ARGS...]: the program on each node count of --nodes, on each machine
// (the calibrated and the published GC unless --config says), each point one mpirun's run.
#include "apps/pipeline/command_groups.hpp"

namespace gcsim::mpi_layer::app {

void add_sweep_mpi(pipeline::CommandGroups& g);

}  // namespace gcsim::mpi_layer::app
