#include "apps/radiosity/cell_assignment.hpp"

#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::radiosity {

CellAssignment parse_cell_assignment(const std::string& s) {
  if (s == "cyclic") return CellAssignment::cyclic;
  if (s == "block") return CellAssignment::block;
  throw std::invalid_argument("unknown cell assignment '" + s + "' (expected cyclic or block)");
}

const char* to_string(CellAssignment a) { return a == CellAssignment::block ? "block" : "cyclic"; }

SideFaces parse_side_faces(const std::string& s) {
  if (s == "half") return SideFaces::half;
  if (s == "full") return SideFaces::full;
  throw std::invalid_argument("unknown side-face layout '" + s + "' (expected half or full)");
}

const char* to_string(SideFaces s) { return s == SideFaces::full ? "full" : "half"; }

namespace {

// The mesh the nodes' shares are cut from: position k holds cell cell_at(k), or none (-1).
class Positions {
 public:
  Positions(int cells, SideFaces s) : full_(s == SideFaces::full), count_(cells) {
    if (!full_) return;
    int t = 2;
    while (3 * std::int64_t(t) * t < cells) t += 2;
    if (3 * std::int64_t(t) * t != cells)
      throw std::invalid_argument(fmt::format("full side faces: {} cells is not a hemicube partition (3 T^2, T even)", cells));
    t_ = t;
    top_ = std::int64_t(t) * t;
    count_ = 5 * top_;
  }
  std::int64_t count() const { return count_; }
  int cell_at(std::int64_t k) const {
    if (!full_ || k < top_) return int(k);
    // A side face in raster order, its top row (next to the top face) first: rows 0..T/2-1 are the
    // cells' rows T/2-1..0 (counted up from the horizon), rows T/2..T-1 the empty lower half.
    const std::int64_t face = (k - top_) / top_, row = (k - top_) % top_ / t_, column = (k - top_) % t_;
    if (row >= t_ / 2) return -1;
    return int(top_ + face * (top_ / 2) + (t_ / 2 - 1 - row) * t_ + column);
  }

 private:
  bool full_;
  std::int64_t count_;
  std::int64_t t_ = 0, top_ = 0;
};

}  // namespace

std::vector<int> cells_of(CellAssignment a, int node, int nodes, int cells, SideFaces s) {
  const Positions mesh(cells, s);
  std::vector<int> out;
  auto take = [&](std::int64_t k) {
    if (const int c = mesh.cell_at(k); c >= 0) out.push_back(c);
  };
  if (a == CellAssignment::cyclic) {
    for (std::int64_t k = node; k < mesh.count(); k += nodes) take(k);
    return out;
  }
  // 64-bit products: positions * nodes may exceed int at 65536 nodes and fine partitions.
  const std::int64_t first = std::int64_t(node) * mesh.count() / nodes;
  const std::int64_t last = std::int64_t(node + 1) * mesh.count() / nodes;
  for (std::int64_t k = first; k < last; ++k) take(k);
  return out;
}

}  // namespace gcsim::radiosity
