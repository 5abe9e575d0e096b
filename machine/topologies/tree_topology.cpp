// Binary tree: processor v's parent is (v - 1) / 2; placed in breadth-first order.
#include <cmath>

#include "machine/topology.hpp"

namespace gcsim::machine::topologies {
namespace {

class BinaryTree final : public TopologyFamily {
 public:
  std::string_view name() const override { return "tree"; }
  VirtualTopology graph(int n) const override {
    VirtualTopology t{name(), 0, 0, std::vector<std::vector<int>>(n)};
    for (int v = 1; v < n; ++v) t.add_edge(v, (v - 1) / 2);
    t.finish();
    return t;
  }
  std::vector<int> placement(const VirtualTopology& t, const Interconnect&) const override {
    std::vector<int> node_of(t.size());
    for (int v = 0; v < t.size(); ++v) node_of[v] = v;
    return node_of;
  }
  // Eqs. 2.8-2.12.
  TopologyMetrics thesis_formulas(int n) const override {
    const double N = n;
    return {2 * std::log2(N), 2 * std::log2(N), 5.0 / 16.0 * N * N, N * std::log2(N), 2, 2 * std::log2(N)};
  }
};

const BinaryTree binary_tree_family;
const TopologyRegistrar binary_tree_topology_registrar{binary_tree_family, 40};

}  // namespace
}  // namespace gcsim::machine::topologies
