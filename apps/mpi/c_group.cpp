// The C entry points of groups. Groups come from communicators (MPI_Comm_group, with the
// runtime); every operation on them is here.
#include <vector>

#include "apps/mpi/c_call.hpp"

using namespace gcsim::mpi_layer;

namespace {

std::vector<int> int_array(const int* p, int n) {
  check_count_arg(n);
  if (n > 0 && !p) fail(MPI_ERR_ARG, "null array argument");
  return std::vector<int>(p, p + n);
}

std::vector<RankRange> range_array(int ranges[][3], int n) {
  check_count_arg(n);
  if (n > 0 && !ranges) fail(MPI_ERR_ARG, "null array argument");
  std::vector<RankRange> out;
  for (int i = 0; i < n; ++i) out.push_back({ranges[i][0], ranges[i][1], ranges[i][2]});
  return out;
}

// Registers a new group; an empty one is MPI_GROUP_EMPTY.
template <class Make>
int make_group(MPI_Group* newgroup, Make make, std::source_location where = std::source_location::current()) {
  return c_call([&](Registry& r) {
    MPI_Group& out = out_arg(newgroup);
    Group g = make(r);
    out = g.size() == 0 ? MPI_GROUP_EMPTY : r.groups.insert(std::move(g));
  }, where);
}

}  // namespace

extern "C" {

int MPI_Group_size(MPI_Group group, int* size) {
  return c_call([&](Registry& r) { out_arg(size) = group_arg(r, group).size(); });
}

int MPI_Group_rank(MPI_Group group, int* rank) {
  return c_call([&](Registry& r) { out_arg(rank) = group_arg(r, group).rank_of(r.world_rank); });
}

int MPI_Group_translate_ranks(MPI_Group group1, int n, const int ranks1[], MPI_Group group2, int ranks2[]) {
  return c_call([&](Registry& r) {
    const std::vector<int> out = translate_ranks(group_arg(r, group1), int_array(ranks1, n), group_arg(r, group2));
    if (n > 0 && !ranks2) fail(MPI_ERR_ARG, "null output array");
    for (int i = 0; i < n; ++i) ranks2[i] = out[static_cast<std::size_t>(i)];
  });
}

int MPI_Group_compare(MPI_Group group1, MPI_Group group2, int* result) {
  return c_call([&](Registry& r) { out_arg(result) = compare_groups(group_arg(r, group1), group_arg(r, group2)); });
}

int MPI_Group_union(MPI_Group group1, MPI_Group group2, MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_union(group_arg(r, group1), group_arg(r, group2)); });
}

int MPI_Group_intersection(MPI_Group group1, MPI_Group group2, MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_intersection(group_arg(r, group1), group_arg(r, group2)); });
}

int MPI_Group_difference(MPI_Group group1, MPI_Group group2, MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_difference(group_arg(r, group1), group_arg(r, group2)); });
}

int MPI_Group_incl(MPI_Group group, int n, const int ranks[], MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_incl(group_arg(r, group), int_array(ranks, n)); });
}

int MPI_Group_excl(MPI_Group group, int n, const int ranks[], MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_excl(group_arg(r, group), int_array(ranks, n)); });
}

int MPI_Group_range_incl(MPI_Group group, int n, int ranges[][3], MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_range_incl(group_arg(r, group), range_array(ranges, n)); });
}

int MPI_Group_range_excl(MPI_Group group, int n, int ranges[][3], MPI_Group* newgroup) {
  return make_group(newgroup, [&](Registry& r) { return group_range_excl(group_arg(r, group), range_array(ranges, n)); });
}

int MPI_Group_free(MPI_Group* group) {
  return c_call([&](Registry& r) {
    MPI_Group& handle = out_arg(group);
    if (handle != MPI_GROUP_EMPTY && !r.groups.erase(handle)) fail(MPI_ERR_GROUP, "invalid group");
    handle = MPI_GROUP_NULL;
  });
}

}  // extern "C"
