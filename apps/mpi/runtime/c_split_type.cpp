// MPI_Comm_split_type (MPI 3.1 section 6.4.2): MPI_COMM_TYPE_SHARED groups the ranks that run on
// one simulated node (they could share memory), a split by the node's number, ordered by key and
// then by rank; MPI_UNDEFINED gives MPI_COMM_NULL. The runtime says which node a rank is on
// (node_of_world_rank), so this holds however many ranks share a node.
#include <string>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

extern "C" {

int MPI_Comm_split_type(MPI_Comm comm, int split_type, int key, MPI_Info info, MPI_Comm* newcomm) {
  (void)info;  // no hints are read
  return runtime_call([&](Rank& rank) {
    rank.comm(comm);
    MPI_Comm& out = out_arg(newcomm);
    if (split_type != MPI_COMM_TYPE_SHARED && split_type != MPI_UNDEFINED) {
      fail(MPI_ERR_ARG, ("MPI_Comm_split_type: unknown split type " + std::to_string(split_type)).c_str());
    }
    const int color = split_type == MPI_UNDEFINED ? MPI_UNDEFINED : node_of_world_rank(rank, rank.world_rank());
    if (const int code = MPI_Comm_split(comm, color, key, &out); code != MPI_SUCCESS) fail(code, "MPI_Comm_split_type: its split failed");
  });
}

}  // extern "C"
