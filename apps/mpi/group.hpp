#pragma once
// Process groups (MPI 3.1 section 6.3): an ordered set of processes, named here by their rank in
// MPI_COMM_WORLD. Constructors check their rank arguments as the standard requires (MPI_ERR_RANK
// for a rank outside the group or listed twice, MPI_ERR_ARG for a bad range).
#include <span>
#include <vector>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

class Group {
 public:
  Group() = default;
  explicit Group(std::vector<int> members);  // distinct world ranks, in group-rank order
  static Group world(int size);              // 0 .. size-1

  int size() const { return static_cast<int>(members_.size()); }
  // The group rank of a world rank, MPI_UNDEFINED if it is not a member.
  int rank_of(int world_rank) const;
  int member(int rank) const { return members_.at(static_cast<std::size_t>(rank)); }
  std::span<const int> members() const { return members_; }

 private:
  std::vector<int> members_;
};

// MPI_Group_translate_ranks: each rank of a in b, MPI_UNDEFINED if absent, MPI_PROC_NULL kept.
std::vector<int> translate_ranks(const Group& a, std::span<const int> ranks, const Group& b);
// MPI_IDENT (same members, same order), MPI_SIMILAR (same members) or MPI_UNEQUAL.
int compare_groups(const Group& a, const Group& b);
// a's members, then b's that are not in a.
Group group_union(const Group& a, const Group& b);
// a's members that are in b, in a's order.
Group group_intersection(const Group& a, const Group& b);
// a's members that are not in b, in a's order.
Group group_difference(const Group& a, const Group& b);
Group group_incl(const Group& g, std::span<const int> ranks);
Group group_excl(const Group& g, std::span<const int> ranks);
// Ranges are (first, last, stride) triplets.
struct RankRange {
  int first, last, stride;
};
Group group_range_incl(const Group& g, std::span<const RankRange> ranges);
Group group_range_excl(const Group& g, std::span<const RankRange> ranges);

}  // namespace gcsim::mpi_layer
