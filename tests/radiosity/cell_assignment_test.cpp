// Which cells each node computes: every cell exactly once, in either assignment and either side-face
// layout, for node counts below, at and above the cell count; block gives contiguous runs differing
// by at most one cell; with full side faces the runs are cut from five equal faces.
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

TEST(CellAssignment, FullSideFacesComputeEveryCellExactlyOnce) {
  for (CellAssignment a : {CellAssignment::cyclic, CellAssignment::block})
    for (int t : {2, 4, 8, 16})
      for (int nodes : {1, 2, 3, 7, 8, 64, 200}) {
        const int cells = 3 * t * t;
        std::vector<int> times(std::size_t(cells), 0);
        for (int r = 0; r < nodes; ++r)
          for (int c : cells_of(a, r, nodes, cells, SideFaces::full)) ++times.at(std::size_t(c));
        EXPECT_TRUE(std::all_of(times.begin(), times.end(), [](int n) { return n == 1; }))
            << to_string(a) << " T " << t << " nodes " << nodes;
      }
}

std::vector<int> range(int first, int last) {  // [first, last)
  std::vector<int> v;
  for (int c = first; c < last; ++c) v.push_back(c);
  return v;
}

TEST(CellAssignment, FullSideFacesCutBlocksFromFiveEqualFaces) {
  // T = 8: the top face is cells 0-63; side face s is cells 64 + 32 s + 8 j + i, its row j counted up
  // from the horizon. The mesh has 320 positions; each side face's 64 run in raster order, its top
  // row (j = 3) first and its empty lower half (32 positions) last.
  const int cells = 192;
  auto block = [&](int node, int nodes) {
    std::vector<int> mine = cells_of(CellAssignment::block, node, nodes, cells, SideFaces::full);
    std::sort(mine.begin(), mine.end());
    return mine;
  };
  auto join = [](std::vector<int> a, const std::vector<int>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  // 2 nodes, 160 positions each: node 0 the top face and side faces 0 and 1; node 1 side faces 2, 3.
  EXPECT_EQ(block(0, 2), range(0, 128));
  EXPECT_EQ(block(1, 2), range(128, 192));
  // 4 nodes, 80 each: node 0 the top face and side face 0's top two rows; node 1 its other two rows
  // and side face 1; nodes 2 and 3 one side face each.
  EXPECT_EQ(block(0, 4), join(range(0, 64), range(80, 96)));
  EXPECT_EQ(block(1, 4), join(range(64, 80), range(96, 128)));
  EXPECT_EQ(block(2, 4), range(128, 160));
  EXPECT_EQ(block(3, 4), range(160, 192));
  // 8 nodes, 40 each: node 0 five eighths of the top face.
  EXPECT_EQ(block(0, 8), range(0, 40));
  EXPECT_EQ(block(1, 8), join(range(40, 64), range(80, 96)));
  // With half side faces the same 8 nodes get 24 cells each.
  EXPECT_EQ(cells_of(CellAssignment::block, 0, 8, cells), range(0, 24));
  // Cyclic deals positions, the empty ones too: node 0 of 64 takes positions 0, 64, ..., 256 (a side
  // face's first position is its top row's first cell), node 32 positions 32, 96, ... (empty but 32).
  EXPECT_EQ(cells_of(CellAssignment::cyclic, 0, 64, cells, SideFaces::full), (std::vector<int>{0, 88, 120, 152, 184}));
  EXPECT_EQ(cells_of(CellAssignment::cyclic, 32, 64, cells, SideFaces::full), (std::vector<int>{32}));
  EXPECT_THROW(cells_of(CellAssignment::block, 0, 2, 190, SideFaces::full), std::invalid_argument);
}

TEST(CellAssignment, NamesParseAndUnknownOnesAreRefused) {
  EXPECT_EQ(parse_cell_assignment("block"), CellAssignment::block);
  EXPECT_EQ(parse_cell_assignment("cyclic"), CellAssignment::cyclic);
  EXPECT_STREQ(to_string(CellAssignment::block), "block");
  EXPECT_THROW(parse_cell_assignment("round-robin"), std::invalid_argument);
  EXPECT_EQ(parse_side_faces("full"), SideFaces::full);
  EXPECT_STREQ(to_string(SideFaces::half), "half");
  EXPECT_THROW(parse_side_faces("whole"), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::radiosity
