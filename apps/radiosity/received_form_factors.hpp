#pragma once
// The delta form factors a node receives in one loop of the parallel solver, kept as they arrived:
// for each shooter and hemicube cell, where the cell's (element, value) pairs start in the
// received bytes. The shooters' rows are summed from there in cell order, the order every replica
// uses, so no per-cell vectors are built (decoding them into vectors was a third of the host time
// of a 64-node CORNELL run, all of it malloc).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "apps/radiosity/hemicube.hpp"
#include "parix/collectives.hpp"
#include "parix/processor.hpp"

namespace gcsim::radiosity {

// The wire format of one cell of one shooter: shooter index k, cell, pair count, then the pairs
// (int32 element, double value).
void put_cell_form_factors(parix::Bytes& out, std::int32_t shooter, const CellFormFactors& c);

class ReceivedFormFactors {
 public:
  // A new loop: `shooters` rows of `cells` cells, none received yet (an unreceived cell is empty).
  void reset(int shooters, int cells);
  // Indexes and keeps a broadcast row, or every node's share; a later copy of a cell replaces an
  // earlier one. Throws std::runtime_error on a truncated or out-of-range message.
  void absorb(parix::Bytes message);
  void absorb(parix::GatheredBytes shares);
  // rows[k][element] += value, cells in order, pairs in order; returns the number of pairs added.
  std::int64_t add_rows(std::vector<std::vector<double>>& rows) const;

 private:
  struct Cell {
    const std::byte* pairs = nullptr;
    std::int32_t count = 0;
  };
  int shooters_ = 0, cells_ = 0;
  void index(std::span<const std::byte> message);
  std::vector<parix::Bytes> held_;  // moving a Bytes keeps its buffer, so Cell::pairs stay valid
  std::vector<Cell> index_;         // [shooter * cells + cell]
};

}  // namespace gcsim::radiosity
