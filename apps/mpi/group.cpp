#include "apps/mpi/group.hpp"

#include <algorithm>
#include <unordered_set>

#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {
namespace {

bool contains(const Group& g, int world_rank) { return g.rank_of(world_rank) != MPI_UNDEFINED; }

// Checks that ranks are distinct ranks of g.
void check_ranks(const Group& g, std::span<const int> ranks) {
  std::vector<bool> seen(static_cast<std::size_t>(g.size()), false);
  for (int r : ranks) {
    if (r < 0 || r >= g.size()) fail(MPI_ERR_RANK, "rank outside the group");
    if (seen[static_cast<std::size_t>(r)]) fail(MPI_ERR_RANK, "rank listed twice");
    seen[static_cast<std::size_t>(r)] = true;
  }
}

// The ranks a list of ranges names, in order; every one must be a rank of g, named once.
std::vector<int> expand_ranges(const Group& g, std::span<const RankRange> ranges) {
  std::vector<int> ranks;
  for (const RankRange& r : ranges) {
    if (r.stride == 0) fail(MPI_ERR_ARG, "range with stride 0");
    for (int x : {r.first, r.last})
      if (x < 0 || x >= g.size()) fail(MPI_ERR_RANK, "range end outside the group");
    if ((r.stride > 0 && r.first > r.last) || (r.stride < 0 && r.first < r.last)) continue;  // empty
    for (long long x = r.first; r.stride > 0 ? x <= r.last : x >= r.last; x += r.stride)
      ranks.push_back(static_cast<int>(x));
  }
  check_ranks(g, ranks);
  return ranks;
}

}  // namespace

Group::Group(std::vector<int> members) : members_(std::move(members)) {}

Group Group::world(int size) {
  std::vector<int> m(static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i) m[static_cast<std::size_t>(i)] = i;
  return Group(std::move(m));
}

int Group::rank_of(int world_rank) const {
  const auto it = std::find(members_.begin(), members_.end(), world_rank);
  return it == members_.end() ? MPI_UNDEFINED : static_cast<int>(it - members_.begin());
}

std::vector<int> translate_ranks(const Group& a, std::span<const int> ranks, const Group& b) {
  std::vector<int> out;
  out.reserve(ranks.size());
  for (int r : ranks) {
    if (r == MPI_PROC_NULL) {
      out.push_back(MPI_PROC_NULL);
      continue;
    }
    if (r < 0 || r >= a.size()) fail(MPI_ERR_RANK, "rank outside the first group");
    out.push_back(b.rank_of(a.member(r)));
  }
  return out;
}

int compare_groups(const Group& a, const Group& b) {
  if (std::ranges::equal(a.members(), b.members())) return MPI_IDENT;
  if (a.size() != b.size()) return MPI_UNEQUAL;
  const bool same_set = std::ranges::all_of(a.members(), [&](int m) { return contains(b, m); });
  return same_set ? MPI_SIMILAR : MPI_UNEQUAL;
}

Group group_union(const Group& a, const Group& b) {
  std::vector<int> m(a.members().begin(), a.members().end());
  for (int x : b.members())
    if (!contains(a, x)) m.push_back(x);
  return Group(std::move(m));
}

Group group_intersection(const Group& a, const Group& b) {
  std::vector<int> m;
  for (int x : a.members())
    if (contains(b, x)) m.push_back(x);
  return Group(std::move(m));
}

Group group_difference(const Group& a, const Group& b) {
  std::vector<int> m;
  for (int x : a.members())
    if (!contains(b, x)) m.push_back(x);
  return Group(std::move(m));
}

Group group_incl(const Group& g, std::span<const int> ranks) {
  check_ranks(g, ranks);
  std::vector<int> m;
  m.reserve(ranks.size());
  for (int r : ranks) m.push_back(g.member(r));
  return Group(std::move(m));
}

Group group_excl(const Group& g, std::span<const int> ranks) {
  check_ranks(g, ranks);
  const std::unordered_set<int> excluded(ranks.begin(), ranks.end());
  std::vector<int> m;
  for (int r = 0; r < g.size(); ++r)
    if (!excluded.contains(r)) m.push_back(g.member(r));
  return Group(std::move(m));
}

Group group_range_incl(const Group& g, std::span<const RankRange> ranges) { return group_incl(g, expand_ranges(g, ranges)); }

Group group_range_excl(const Group& g, std::span<const RankRange> ranges) { return group_excl(g, expand_ranges(g, ranges)); }

}  // namespace gcsim::mpi_layer
