#include "parix/placement.hpp"

#include <fmt/format.h>

#include "parix/processor.hpp"

namespace gcsim::parix {

namespace {

// More processors than nodes: each on a node 0..nodes-1, and no node left empty.
std::vector<int> checked_packing(const std::vector<int>& placement, int nodes) {
  std::vector<bool> used(static_cast<std::size_t>(nodes), false);
  for (std::size_t i = 0; i < placement.size(); ++i) {
    const int n = placement[i];
    if (n < 0 || n >= nodes) throw ParixError(fmt::format("placement puts processor {} on node {} (expected 0..{})", i, n, nodes - 1));
    used[static_cast<std::size_t>(n)] = true;
  }
  for (int n = 0; n < nodes; ++n) {
    if (!used[static_cast<std::size_t>(n)]) {
      throw ParixError(fmt::format("placement of {} processors leaves node {} empty (expected every node 0..{} used)",
                                   placement.size(), n, nodes - 1));
    }
  }
  return placement;
}

}  // namespace

std::vector<int> checked_placement(const std::vector<int>& placement, int nodes) {
  std::vector<int> node_of(nodes);
  if (placement.empty()) {
    for (int i = 0; i < nodes; ++i) node_of[i] = i;
    return node_of;
  }
  if (static_cast<int>(placement.size()) > nodes) return checked_packing(placement, nodes);
  if (static_cast<int>(placement.size()) != nodes) {
    throw ParixError(fmt::format("placement names {} nodes for {} processors (expected one node per processor)",
                                 placement.size(), nodes));
  }
  std::vector<bool> used(nodes, false);
  for (int i = 0; i < nodes; ++i) {
    const int n = placement[i];
    if (n < 0 || n >= nodes || used[n]) {
      throw ParixError(fmt::format("placement puts processor {} on node {} (expected each node 0..{} once)", i, n, nodes - 1));
    }
    used[n] = true;
    node_of[i] = n;
  }
  return node_of;
}

}  // namespace gcsim::parix
