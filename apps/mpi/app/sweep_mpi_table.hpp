#pragma once
// The table of `gcsim sweep mpi`: per node count, the simulated time, the speedup over the
// machine's first count and the parallel efficiency (speedup * first count / count), and where
// the processors' time went (means per processor: busy, communicating, waiting; docs/run-records.md),
// with the machine each row ran on, so that one CSV holds a series per machine for `gcsim plot --sweep`.
#include <memory>
#include <string>

#include "apps/pipeline/sweep_table.hpp"

namespace gcsim::mpi_layer::app {

// machine: the CSV column's value for every row ("calibrated", "published", a file's stem).
std::unique_ptr<pipeline::SweepTable> mpi_sweep_table(std::string machine);

}  // namespace gcsim::mpi_layer::app
