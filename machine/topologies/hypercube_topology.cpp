// Hypercube: processors differing in one address bit are neighbours; the low address bits run
// along the interconnect's x, the high bits along y.
#include <cmath>
#include <stdexcept>
#include <string>

#include "machine/topology.hpp"

namespace gcsim::machine::topologies {
namespace {

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

class Hypercube final : public TopologyFamily {
 public:
  std::string_view name() const override { return "hypercube"; }
  VirtualTopology graph(int n) const override {
    if (!is_power_of_two(n)) {
      throw std::invalid_argument("a hypercube needs a power-of-two processor count, not " + std::to_string(n));
    }
    VirtualTopology t{name(), 0, 0, std::vector<std::vector<int>>(n)};
    for (int v = 0; v < n; ++v) {
      for (int bit = 1; bit < n; bit <<= 1) {
        if ((v ^ bit) > v) t.add_edge(v, v ^ bit);
      }
    }
    t.finish();
    return t;
  }
  std::vector<int> placement(const VirtualTopology& t, const Interconnect& net) const override {
    const int n = t.size();
    int xbits = 0;
    while ((1 << (xbits + 1)) <= net.width() && (1 << (xbits + 1)) <= n) ++xbits;
    const int xmask = (1 << xbits) - 1;
    std::vector<int> node_of(n);
    for (int v = 0; v < n; ++v) node_of[v] = net.node_at(v & xmask, v >> xbits);
    return node_of;
  }
  // Eqs. 2.13-2.17.
  TopologyMetrics thesis_formulas(int n) const override {
    const double N = n;
    return {std::log2(N), std::log2(N) / 2, N * std::log2(N) / 4, N * std::log2(N) / 4, std::log2(N), std::log2(N)};
  }
};

const Hypercube hypercube_family;
const TopologyRegistrar hypercube_topology_registrar{hypercube_family, 50};

}  // namespace
}  // namespace gcsim::machine::topologies
