#pragma once
// gcsim sweep mpi's command line, read by hand as mpirun's is: gcsim's options before the program,
// the program's arguments after it. The sweep's own options (--nodes, --config, --model, --csv,
// --json) may also end the line after the program's arguments, as in
//   gcsim sweep mpi ./jacobi 48 400 --nodes 1,2,4,8
// unless `--` stands before the program's arguments (then every word after it is the program's).
#include <string>
#include <vector>

#include "apps/mpi/app/mpirun_options.hpp"

namespace gcsim::mpi_layer::app {

// A machine the sweep runs on: a machine file, or one of the two built into gcsim.
struct SweepMachine {
  std::string label;   // the CSV's machine column: "calibrated", "published" or the file's stem
  std::string file;    // "" : built in
  bool published = false;  // built in: the GC as published (else as measured, the default machine)
};

struct SweepMpiOptions {
  MpirunOptions run;  // program, arguments, --compute, --coll, --stack-size, --model (np: per point)
  std::vector<int> nodes{1, 2, 4, 8, 16, 32, 64};
  std::vector<SweepMachine> machines;  // --config F, each once; none given: calibrated and published
  std::string csv, json;
  bool help = false;
};

// Throws CLI::ValidationError (exit 2) naming the option and what was expected.
SweepMpiOptions parse_sweep_mpi_options(const std::vector<std::string>& words);
std::string sweep_mpi_summary();
std::string sweep_mpi_usage();

}  // namespace gcsim::mpi_layer::app
