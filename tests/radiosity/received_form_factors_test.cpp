// The form factors a node receives in a loop: indexed where they arrived, summed into rows in cell
// order (as the per-cell vectors they replace were), later copies winning, bad messages refused.
#include "apps/radiosity/received_form_factors.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace gcsim::radiosity {
namespace {

CellFormFactors cell(int c, std::vector<int> elements, std::vector<double> values) {
  return {c, std::move(elements), std::move(values)};
}

TEST(ReceivedFormFactors, RowsAreTheCellsSummedInCellOrder) {
  // Two nodes' shares of two shooters over three cells, cells interleaved as the nodes own them.
  parix::Bytes node0, node1;
  put_cell_form_factors(node0, 0, cell(0, {2, 0}, {0.25, -1.0}));
  put_cell_form_factors(node0, 0, cell(2, {0}, {1e-17}));
  put_cell_form_factors(node0, 1, cell(0, {1}, {0.5}));
  put_cell_form_factors(node1, 0, cell(1, {0, 2}, {1.0, 0.125}));
  put_cell_form_factors(node1, 1, cell(1, {1}, {0.75}));
  ReceivedFormFactors r;
  r.reset(2, 3);
  r.absorb(node0);
  r.absorb(node1);
  std::vector<std::vector<double>> rows(2, std::vector<double>(3, 0.0));
  EXPECT_EQ(r.add_rows(rows), 7);
  // Element 0 of shooter 0 in cell order, (-1 + 1) + 1e-17, keeps the 1e-17 that arrival order,
  // (-1 + 1e-17) + 1, would round away.
  EXPECT_EQ(rows[0][0], 1e-17);
  EXPECT_EQ(rows[0][2], 0.25 + 0.125);
  EXPECT_EQ(rows[1][1], 0.5 + 0.75);
  EXPECT_EQ(rows[1][0], 0.0);
}

TEST(ReceivedFormFactors, ALaterCopyOfACellReplacesTheEarlierAndResetForgets) {
  parix::Bytes first, second;
  put_cell_form_factors(first, 0, cell(1, {0}, {2.0}));
  put_cell_form_factors(second, 0, cell(1, {1}, {3.0}));
  ReceivedFormFactors r;
  r.reset(1, 2);
  r.absorb(first);
  r.absorb(second);
  std::vector<std::vector<double>> rows(1, std::vector<double>(2, 0.0));
  EXPECT_EQ(r.add_rows(rows), 1);
  EXPECT_EQ(rows[0], (std::vector<double>{0.0, 3.0}));
  r.reset(1, 2);
  std::vector<std::vector<double>> empty(1, std::vector<double>(2, 0.0));
  EXPECT_EQ(r.add_rows(empty), 0);
  EXPECT_EQ(empty[0], (std::vector<double>{0.0, 0.0}));
}

TEST(ReceivedFormFactors, BadMessagesAreRefused) {
  ReceivedFormFactors r;
  r.reset(1, 2);
  parix::Bytes truncated;
  put_cell_form_factors(truncated, 0, cell(0, {0, 1}, {1.0, 2.0}));
  truncated.resize(truncated.size() - 1);
  EXPECT_THROW(r.absorb(truncated), std::runtime_error);
  parix::Bytes bad_cell, bad_shooter, bad_element;
  put_cell_form_factors(bad_cell, 0, cell(2, {0}, {1.0}));
  put_cell_form_factors(bad_shooter, 1, cell(0, {0}, {1.0}));
  EXPECT_THROW(r.absorb(bad_cell), std::runtime_error);
  EXPECT_THROW(r.absorb(bad_shooter), std::runtime_error);
  r.reset(1, 2);
  put_cell_form_factors(bad_element, 0, cell(0, {5}, {1.0}));
  r.absorb(bad_element);
  std::vector<std::vector<double>> rows(1, std::vector<double>(2, 0.0));
  EXPECT_THROW(r.add_rows(rows), std::runtime_error);
}

}  // namespace
}  // namespace gcsim::radiosity
