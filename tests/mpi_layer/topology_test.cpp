// Topology arithmetic: MPI_Dims_create, Cartesian coordinates, shifts and sub-grids, graphs.
#include <gtest/gtest.h>

#include <vector>

#include "apps/mpi/error.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"
#include "apps/mpi/topology.hpp"

namespace gcsim::mpi_layer {
namespace {

std::vector<int> dims_of(int nnodes, std::vector<int> dims) {
  dims_create(nnodes, dims);
  return dims;
}

TEST(MpiDimsCreate, TheStandardsExamples) {
  EXPECT_EQ(dims_of(6, {0, 0}), (std::vector<int>{3, 2}));
  EXPECT_EQ(dims_of(7, {0, 0}), (std::vector<int>{7, 1}));
  EXPECT_EQ(dims_of(6, {0, 3, 0}), (std::vector<int>{2, 3, 1}));
  EXPECT_EQ(error_of([] { dims_of(7, {0, 3, 0}); }), MPI_ERR_DIMS);
}

TEST(MpiDimsCreate, BalancedAndNonIncreasing) {
  EXPECT_EQ(dims_of(64, {0, 0}), (std::vector<int>{8, 8}));
  EXPECT_EQ(dims_of(64, {0, 0, 0}), (std::vector<int>{4, 4, 4}));
  EXPECT_EQ(dims_of(32, {0, 0}), (std::vector<int>{8, 4}));
  EXPECT_EQ(dims_of(12, {0, 0, 0}), (std::vector<int>{3, 2, 2}));
  EXPECT_EQ(dims_of(36, {0, 0, 0}), (std::vector<int>{4, 3, 3}));
  // The most balanced split of 2^4 * 3^2 into three factors.
  EXPECT_EQ(dims_of(144, {0, 0, 0}), (std::vector<int>{6, 6, 4}));
  EXPECT_EQ(dims_of(1, {0, 0}), (std::vector<int>{1, 1}));
  EXPECT_EQ(dims_of(24, {0, 2, 0}), (std::vector<int>{4, 2, 3}));
  EXPECT_EQ(dims_of(8, {2, 4}), (std::vector<int>{2, 4}));
  EXPECT_TRUE(dims_of(1, {}).empty());
  for (int n = 1; n <= 200; ++n) {
    const std::vector<int> d = dims_of(n, {0, 0, 0});
    EXPECT_EQ(d[0] * d[1] * d[2], n);
    EXPECT_GE(d[0], d[1]);
    EXPECT_GE(d[1], d[2]);
  }
}

TEST(MpiDimsCreate, Errors) {
  EXPECT_EQ(error_of([] { dims_of(8, {2, 3}); }), MPI_ERR_DIMS);
  EXPECT_EQ(error_of([] { dims_of(8, {-1, 0}); }), MPI_ERR_DIMS);
  EXPECT_EQ(error_of([] { dims_of(0, {0}); }), MPI_ERR_ARG);
  EXPECT_EQ(error_of([] { dims_of(8, {16, 0}); }), MPI_ERR_DIMS);
  EXPECT_EQ(error_of([] { dims_of(5, {}); }), MPI_ERR_DIMS);  // no dimensions hold one node only
}

TEST(MpiCartTopology, RowMajorRanksAndCoordinates) {
  const CartTopology t({2, 3, 4}, {false, false, false});
  EXPECT_EQ(t.size(), 24);
  EXPECT_EQ(t.rank(std::vector<int>{1, 2, 3}), 23);
  EXPECT_EQ(t.rank(std::vector<int>{0, 1, 0}), 4);
  EXPECT_EQ(t.coords(17), (std::vector<int>{1, 1, 1}));
  for (int r = 0; r < t.size(); ++r) EXPECT_EQ(t.rank(t.coords(r)), r);
  EXPECT_EQ(error_of([&] { t.rank(std::vector<int>{2, 0, 0}); }), MPI_ERR_ARG);
  EXPECT_EQ(error_of([&] { t.coords(24); }), MPI_ERR_RANK);
}

TEST(MpiCartTopology, PeriodicCoordinatesWrap) {
  const CartTopology t({3, 4}, {true, false});
  EXPECT_EQ(t.rank(std::vector<int>{-1, 2}), t.rank(std::vector<int>{2, 2}));
  EXPECT_EQ(t.rank(std::vector<int>{7, 0}), t.rank(std::vector<int>{1, 0}));
  EXPECT_EQ(error_of([&] { t.rank(std::vector<int>{0, 4}); }), MPI_ERR_ARG);
}

TEST(MpiCartTopology, ShiftGivesProcNullOffNonPeriodicEnds) {
  const CartTopology t({3, 4}, {true, false});
  const int corner = t.rank(std::vector<int>{0, 0});
  // Periodic dimension 0: source wraps to the last row.
  EXPECT_EQ(t.shift(corner, 0, 1), std::make_pair(t.rank(std::vector<int>{2, 0}), t.rank(std::vector<int>{1, 0})));
  // Non-periodic dimension 1.
  EXPECT_EQ(t.shift(corner, 1, 1), std::make_pair(MPI_PROC_NULL, t.rank(std::vector<int>{0, 1})));
  EXPECT_EQ(t.shift(t.rank(std::vector<int>{1, 3}), 1, 1), std::make_pair(t.rank(std::vector<int>{1, 2}), MPI_PROC_NULL));
  EXPECT_EQ(t.shift(corner, 1, -2), std::make_pair(t.rank(std::vector<int>{0, 2}), MPI_PROC_NULL));
  EXPECT_EQ(t.shift(corner, 0, 4), t.shift(corner, 0, 1));
  EXPECT_EQ(t.shift(corner, 1, 0), std::make_pair(corner, corner));
  EXPECT_EQ(error_of([&] { t.shift(corner, 2, 1); }), MPI_ERR_ARG);
}

TEST(MpiCartTopology, SubGridsSplitByTheDroppedCoordinates) {
  const CartTopology t({2, 3, 4}, {true, false, true});
  const std::vector<bool> remain{true, false, true};
  const CartTopology s = t.sub(remain);
  EXPECT_EQ(std::vector<int>(s.dims().begin(), s.dims().end()), (std::vector<int>{2, 4}));
  EXPECT_TRUE(s.periodic(0));
  EXPECT_TRUE(s.periodic(1));
  // Every sub-grid holds each of its ranks once; members share the dropped coordinate.
  std::vector<std::vector<int>> seen(3, std::vector<int>(8, 0));
  for (int r = 0; r < t.size(); ++r) {
    const int color = t.sub_color(r, remain), rank = t.sub_rank(r, remain);
    EXPECT_EQ(color, t.coords(r)[1]);
    EXPECT_EQ(s.coords(rank), (std::vector<int>{t.coords(r)[0], t.coords(r)[2]}));
    ++seen[color][rank];
  }
  for (const auto& grid : seen)
    for (int n : grid) EXPECT_EQ(n, 1);
  // Dropping every dimension leaves zero-dimensional grids of one process.
  EXPECT_EQ(t.sub(std::vector<bool>{false, false, false}).size(), 1);
  EXPECT_EQ(t.map(23), 23);
  EXPECT_EQ(t.map(24), MPI_UNDEFINED);
}

TEST(MpiGraphTopology, NeighboursFromIndexAndEdges) {
  // The standard's example: 4 nodes, 0-1 0-3 1-0 2-3 3-0 3-2.
  const GraphTopology g({2, 3, 4, 6}, {1, 3, 0, 3, 0, 2});
  EXPECT_EQ(g.nnodes(), 4);
  EXPECT_EQ(g.nedges(), 6);
  EXPECT_EQ(g.neighbors_count(0), 2);
  EXPECT_EQ(std::vector<int>(g.neighbors(3).begin(), g.neighbors(3).end()), (std::vector<int>{0, 2}));
  EXPECT_EQ(std::vector<int>(g.neighbors(1).begin(), g.neighbors(1).end()), (std::vector<int>{0}));
  EXPECT_EQ(error_of([&] { g.neighbors(4); }), MPI_ERR_RANK);
  EXPECT_EQ(error_of([] { GraphTopology({2, 1}, {1, 0}); }), MPI_ERR_ARG);
  EXPECT_EQ(error_of([] { GraphTopology({1}, {5}); }), MPI_ERR_ARG);
  EXPECT_EQ(g.map(5), MPI_UNDEFINED);
}

}  // namespace
}  // namespace gcsim::mpi_layer
