// Which cells each node computes: every cell exactly once, in either assignment, for node counts
// below, at and above the cell count; block gives contiguous runs differing by at most one cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "apps/radiosity/cell_assignment.hpp"

namespace gcsim::radiosity {
namespace {

TEST(CellAssignment, EveryCellIsComputedByExactlyOneNode) {
  for (CellAssignment a : {CellAssignment::cyclic, CellAssignment::block})
    for (int cells : {1, 12, 48, 192})
      for (int nodes : {1, 2, 3, 7, 8, 64, 200}) {
        std::vector<int> times(std::size_t(cells), 0);
        for (int r = 0; r < nodes; ++r)
          for (int c : cells_of(a, r, nodes, cells)) ++times.at(std::size_t(c));
        EXPECT_TRUE(std::all_of(times.begin(), times.end(), [](int t) { return t == 1; }))
            << to_string(a) << " cells " << cells << " nodes " << nodes;
      }
}

TEST(CellAssignment, CyclicDealsCellsInTurnAndBlockCutsContiguousRuns) {
  EXPECT_EQ(cells_of(CellAssignment::cyclic, 1, 4, 10), (std::vector<int>{1, 5, 9}));
  // 192 cells on 5 nodes: runs of 38 or 39, in node order.
  int next = 0;
  for (int r = 0; r < 5; ++r) {
    const std::vector<int> mine = cells_of(CellAssignment::block, r, 5, 192);
    ASSERT_FALSE(mine.empty());
    EXPECT_EQ(mine.front(), next);
    EXPECT_EQ(mine.back() - mine.front() + 1, int(mine.size()));
    EXPECT_TRUE(mine.size() == 38 || mine.size() == 39) << mine.size();
    next = mine.back() + 1;
  }
  EXPECT_EQ(next, 192);
  // More nodes than cells: some nodes compute nothing, none computes twice.
  EXPECT_TRUE(cells_of(CellAssignment::block, 0, 64, 48).empty());
  EXPECT_EQ(cells_of(CellAssignment::block, 63, 64, 48), (std::vector<int>{47}));
}

TEST(CellAssignment, NamesParseAndUnknownOnesAreRefused) {
  EXPECT_EQ(parse_cell_assignment("block"), CellAssignment::block);
  EXPECT_EQ(parse_cell_assignment("cyclic"), CellAssignment::cyclic);
  EXPECT_STREQ(to_string(CellAssignment::block), "block");
  EXPECT_THROW(parse_cell_assignment("round-robin"), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::radiosity
