// Process groups: the standard's set operations, inclusions, ranges, translation and comparison.
#include <gtest/gtest.h>

#include <vector>

#include "apps/mpi/error.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"
#include "apps/mpi/group.hpp"

namespace gcsim::mpi_layer {
namespace {

std::vector<int> members(const Group& g) { return {g.members().begin(), g.members().end()}; }

const Group world = Group::world(8);

TEST(MpiGroup, RanksAndMembers) {
  const Group g({5, 2, 7});
  EXPECT_EQ(g.size(), 3);
  EXPECT_EQ(g.rank_of(2), 1);
  EXPECT_EQ(g.rank_of(3), MPI_UNDEFINED);
  EXPECT_EQ(Group().size(), 0);
}

TEST(MpiGroup, SetOperationsKeepTheFirstGroupsOrder) {
  const Group a({1, 4, 6, 2}), b({2, 3, 4});
  EXPECT_EQ(members(group_union(a, b)), (std::vector<int>{1, 4, 6, 2, 3}));
  EXPECT_EQ(members(group_intersection(a, b)), (std::vector<int>{4, 2}));
  EXPECT_EQ(members(group_difference(a, b)), (std::vector<int>{1, 6}));
  EXPECT_EQ(group_difference(a, a).size(), 0);
  EXPECT_EQ(members(group_union(Group(), b)), members(b));
}

TEST(MpiGroup, InclExclFollowTheListedOrder) {
  const std::vector<int> ranks{6, 0, 3};
  EXPECT_EQ(members(group_incl(world, ranks)), ranks);
  EXPECT_EQ(members(group_excl(world, ranks)), (std::vector<int>{1, 2, 4, 5, 7}));
  EXPECT_EQ(group_incl(world, {}).size(), 0);
  EXPECT_EQ(members(group_incl(group_incl(world, ranks), std::vector<int>{2})), (std::vector<int>{3}));
  EXPECT_EQ(error_of([] { group_incl(world, std::vector<int>{1, 1}); }), MPI_ERR_RANK);
  EXPECT_EQ(error_of([] { group_excl(world, std::vector<int>{8}); }), MPI_ERR_RANK);
}

TEST(MpiGroup, RangesWithPositiveAndNegativeStrides) {
  const std::vector<RankRange> ranges{{1, 7, 3}, {6, 2, -4}};  // 1 4 7, then 6 2
  EXPECT_EQ(members(group_range_incl(world, ranges)), (std::vector<int>{1, 4, 7, 6, 2}));
  EXPECT_EQ(members(group_range_excl(world, ranges)), (std::vector<int>{0, 3, 5}));
  EXPECT_EQ(group_range_incl(world, std::vector<RankRange>{{5, 5, 1}}).size(), 1);
  EXPECT_EQ(error_of([] { group_range_incl(world, std::vector<RankRange>{{0, 3, 0}}); }), MPI_ERR_ARG);
  EXPECT_EQ(error_of([] { group_range_incl(world, std::vector<RankRange>{{0, 9, 1}}); }), MPI_ERR_RANK);
  EXPECT_EQ(error_of([] { group_range_incl(world, std::vector<RankRange>{{0, 4, 2}, {4, 5, 1}}); }), MPI_ERR_RANK);
}

TEST(MpiGroup, TranslateRanks) {
  const Group a({3, 5, 1}), b({1, 2, 3});
  const std::vector<int> ranks{0, 1, 2, MPI_PROC_NULL};
  EXPECT_EQ(translate_ranks(a, ranks, b), (std::vector<int>{2, MPI_UNDEFINED, 0, MPI_PROC_NULL}));
  EXPECT_EQ(error_of([&] { translate_ranks(a, std::vector<int>{3}, b); }), MPI_ERR_RANK);
}

TEST(MpiGroup, Compare) {
  EXPECT_EQ(compare_groups(Group({1, 2, 3}), Group({1, 2, 3})), MPI_IDENT);
  EXPECT_EQ(compare_groups(Group({1, 2, 3}), Group({3, 1, 2})), MPI_SIMILAR);
  EXPECT_EQ(compare_groups(Group({1, 2, 3}), Group({1, 2, 4})), MPI_UNEQUAL);
  EXPECT_EQ(compare_groups(Group({1, 2}), Group({1, 2, 3})), MPI_UNEQUAL);
  EXPECT_EQ(compare_groups(Group(), Group()), MPI_IDENT);
}

}  // namespace
}  // namespace gcsim::mpi_layer
