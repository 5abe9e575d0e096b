#pragma once
// What MPI_Comm_dup, MPI_Comm_free and MPI_Finalize do with a communicator's attributes (MPI 3.1
// sections 6.7.2, 8.7.1): run the keys' copy and delete callbacks (c_attributes.cpp).
#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

// Every attribute of `from` whose key's copy callback sets its flag, onto `to`, in key order;
// fails with a callback's error code.
void copy_attributes(Rank& rank, MPI_Comm from, MPI_Comm to);
// Every attribute of comm deleted in key order, its delete callback called; fails with the first
// callback error, the attributes after it kept.
void delete_attributes(Rank& rank, MPI_Comm comm);

}  // namespace gcsim::mpi_layer
