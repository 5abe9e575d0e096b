#include "parix/placement.hpp"

#include <fmt/format.h>

#include "parix/processor.hpp"

namespace gcsim::parix {

std::vector<int> checked_placement(const std::vector<int>& placement, int nodes) {
  std::vector<int> node_of(nodes);
  if (placement.empty()) {
    for (int i = 0; i < nodes; ++i) node_of[i] = i;
    return node_of;
  }
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
