#pragma once
// The deadlock report of an MPI run in the program's words: each blocked processor is the rank of
// the same number (one rank per node), so "  processor 1: blocked in MPI_Send(...)" becomes
// "  rank 1: blocked in MPI_Send(...)". PARIX programs keep the runtime's "processor".
#include <string>

namespace gcsim::mpi_layer::app {

std::string rank_deadlock_report(const std::string& report);

}  // namespace gcsim::mpi_layer::app
