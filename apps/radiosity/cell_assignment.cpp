#include "apps/radiosity/cell_assignment.hpp"

#include <cstdint>
#include <stdexcept>

namespace gcsim::radiosity {

CellAssignment parse_cell_assignment(const std::string& s) {
  if (s == "cyclic") return CellAssignment::cyclic;
  if (s == "block") return CellAssignment::block;
  throw std::invalid_argument("unknown cell assignment '" + s + "' (expected cyclic or block)");
}

const char* to_string(CellAssignment a) { return a == CellAssignment::block ? "block" : "cyclic"; }

std::vector<int> cells_of(CellAssignment a, int node, int nodes, int cells) {
  std::vector<int> out;
  if (a == CellAssignment::cyclic) {
    for (int c = node; c < cells; c += nodes) out.push_back(c);
    return out;
  }
  // 64-bit products: cells * nodes may exceed int at 65536 nodes and fine partitions.
  const int first = int(std::int64_t(node) * cells / nodes), last = int(std::int64_t(node + 1) * cells / nodes);
  for (int c = first; c < last; ++c) out.push_back(c);
  return out;
}

}  // namespace gcsim::radiosity
