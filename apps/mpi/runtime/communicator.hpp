#pragma once
// A communicator of the runtime: its members (world ranks in communicator-rank order), this rank's
// place among them, and its context. Every rank of a communicator derives the same context for a
// child (dup, split, create) without talking: a hash of the parent's and the child's number, so
// contexts never need agreeing on. Point-to-point uses the even context, collectives the odd one
// next to it, so no user receive, wildcards included, ever matches a collective's message.
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "apps/mpi/topology.hpp"

namespace gcsim::mpi_layer {

struct Communicator {
  std::shared_ptr<const std::vector<int>> members;  // world ranks; shared with requests
  int rank = 0;                                      // this rank in the communicator
  std::int64_t context = 0;                          // even: point-to-point; context + 1: collectives
  std::int64_t children = 0;                         // contexts derived from this one so far
  std::shared_ptr<const CartTopology> cart;  // MPI_Cart_create's grid, if it made this one
  std::uint32_t collectives = 0;  // collectives started on it: the next one's sequence number
  int errhandler = 1;  // MPI_ERRORS_ARE_FATAL, the standard's default; a child inherits its parent's
  int handle = 0;      // its MPI_Comm, set by Rank::add_comm
  std::shared_ptr<const GraphTopology> graph = nullptr;  // MPI_Graph_create's graph, if it made this one
  std::map<int, void*> attributes{};           // keyval -> value (MPI_Comm_set_attr)

  int size() const { return static_cast<int>(members->size()); }
  int world_rank_of(int rank_in_comm) const { return (*members)[static_cast<std::size_t>(rank_in_comm)]; }
  // The communicator rank of a world rank; -1 if it is not a member.
  int rank_of_world(int world) const {
    for (std::size_t i = 0; i < members->size(); ++i) {
      if ((*members)[i] == world) return static_cast<int>(i);
    }
    return -1;
  }
  std::int64_t collective_context() const { return context + 1; }
  // The child made of this communicator's first n members, in order (a Cartesian or graph
  // topology's communicator): members shared when it is the whole, the error handler inherited.
  Communicator first_members(int n, std::int64_t child_context) const {
    Communicator c;
    c.rank = rank;
    c.members = n == size() ? members : std::make_shared<const std::vector<int>>(members->begin(), members->begin() + n);
    c.context = child_context;
    c.errhandler = errhandler;  // inherited (MPI 3.1 section 8.3.1)
    return c;
  }
  // The context of the next child: the same on every member, as each derives children in the
  // same collective order.
  std::int64_t next_child_context() {
    std::uint64_t z = static_cast<std::uint64_t>(context) * 0x9e3779b97f4a7c15ull + static_cast<std::uint64_t>(++children);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<std::int64_t>((z >> 2) << 1) + 16;  // even, clear of the predefined ones
  }
};

}  // namespace gcsim::mpi_layer
