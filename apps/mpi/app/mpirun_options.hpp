#pragma once
// gcsim mpirun's command line, read by hand: Open MPI's spelling `-np N` is not an option name
// CLI11 accepts, and everything after the program belongs to the program.
#include <cstdint>
#include <string>
#include <vector>

#include "apps/mpi/collective_selection.hpp"
#include "apps/mpi/runtime/host_speed.hpp"
#include "apps/pipeline/machine_options.hpp"

namespace gcsim::mpi_layer::app {

struct MpirunOptions {
  int np = 0;
  int ranks_per_node = 1;  // --ranks-per-node K: rank r on node r / K, ceil(np / K) nodes
  pipeline::MachineOptions machine;  // --config, --model, --shape, --json, --trace
  bool tag_output = false;
  std::int64_t stack_bytes = std::int64_t{8} << 20;  // per rank, reserved and committed as used
  std::string compute = "measured";                  // none | annotated | measured (runtime/compute_meter.hpp)
  HostSpeedChoice host_speed;                        // --host-speed auto | RATIO | RATE
  AlgorithmChoice collectives;                       // --coll bcast=binomial,...; Auto elsewhere
  std::string collectives_spec;                      // --coll's text, for the run's JSON
  std::string program;
  std::vector<std::string> args;
  bool help = false;
};

// Throws CLI::ValidationError (exit 2) naming the option and what was expected.
MpirunOptions parse_mpirun_options(const std::vector<std::string>& words);
std::string mpirun_summary();
std::string mpirun_usage();

}  // namespace gcsim::mpi_layer::app
