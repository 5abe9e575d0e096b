#pragma once
// Mismatched collectives found when they are called (MPI 3.1 section 5.1: every rank of a
// communicator calls the same collective, with the same root and op, and type signatures that
// match). All ranks of `gcsim mpirun` live in one gcsim process, so each call's signature is
// recorded host-side per (collective context, first member, sequence number; the groups of one
// MPI_Comm_split share a context, being disjoint) and compared with the first
// arrival's as the others arrive: no simulated cost, no extra message, the same on every run.
// The first arrival goes on (it cannot know yet); a later one that disagrees fails with the class
// of the first difference, naming both calls. Forgotten once every member has arrived.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "apps/mpi/datatype.hpp"
#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

struct CollectiveSignature {
  std::string call;          // "MPI_Reduce"
  int root = -1;             // rooted collectives only
  MPI_Op op = MPI_OP_NULL;   // reductions; user ops are compared as "a user op" (handles are per rank)
  // Where every rank's block has one type signature: count x type (compared by type_transfer.hpp's
  // match_signatures, so MPI_PACKED matches any type byte for byte).
  std::optional<Datatype> type;
  MPI_Count count = 0;
  std::string data_text;     // "4 x MPI_INT"
  std::string text() const;  // "MPI_Reduce(root=1, op=MPI_SUM, 4 x MPI_INT)"
};

class CollectiveLedger {
 public:
  // Throws Error (MPI_ERR_OTHER: another collective; MPI_ERR_ROOT, MPI_ERR_OP, MPI_ERR_TYPE or
  // MPI_ERR_COUNT) if mine disagrees with the first rank's call of this (context, sequence).
  // first_member: the world rank of the communicator's rank 0.
  void arrive(std::int64_t context, int first_member, std::uint32_t sequence, int comm_size, int comm_rank,
              const std::string& comm_name, const CollectiveSignature& mine);

 private:
  struct Entry {
    CollectiveSignature first;
    int first_rank = 0;
    int arrived = 0;
  };
  std::map<std::tuple<std::int64_t, int, std::uint32_t>, Entry> entries_;
};

}  // namespace gcsim::mpi_layer
