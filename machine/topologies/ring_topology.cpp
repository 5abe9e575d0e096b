// Ring: processor v next to v - 1 and v + 1 (mod n), laid along a Hamiltonian cycle of the grid of nodes.
#include "machine/topology.hpp"

namespace gcsim::machine::topologies {
namespace {

// Nodes in the order of a Hamiltonian cycle of the grid (height even, or width even by symmetry), or of a
// boustrophedon path when neither dimension is even.
std::vector<int> ring_order(const Interconnect& net, int n) {
  const int w = net.width(), h = net.height();
  std::vector<int> order;
  if (n != w * h) {
    for (int v = 0; v < n; ++v) order.push_back(v);
    return order;
  }
  auto walk = [&](bool transpose) {
    const int W = transpose ? h : w, H = transpose ? w : h;
    auto at = [&](int x, int y) { return transpose ? net.node_at(y, x) : net.node_at(x, y); };
    std::vector<int> o;
    for (int y = 0; y < H; ++y) {
      if (y % 2 == 0) {
        for (int x = (y == 0 ? 0 : 1); x < W; ++x) o.push_back(at(x, y));
      } else {
        for (int x = W - 1; x >= 1; --x) o.push_back(at(x, y));
      }
    }
    for (int y = H - 1; y >= 1; --y) o.push_back(at(0, y));
    return o;
  };
  if (w >= 2 && h >= 2 && h % 2 == 0) return walk(false);
  if (w >= 2 && h >= 2 && w % 2 == 0) return walk(true);
  for (int y = 0; y < h; ++y) {
    for (int i = 0; i < w; ++i) order.push_back(net.node_at(y % 2 == 0 ? i : w - 1 - i, y));
  }
  return order;
}

class Ring final : public TopologyFamily {
 public:
  std::string_view name() const override { return "ring"; }
  VirtualTopology graph(int n) const override {
    VirtualTopology t{name(), 0, 0, std::vector<std::vector<int>>(n)};
    for (int v = 0; v + 1 < n; ++v) t.add_edge(v, v + 1);
    if (n > 2) t.add_edge(n - 1, 0);
    t.finish();
    return t;
  }
  std::vector<int> placement(const VirtualTopology& t, const Interconnect& net) const override {
    return ring_order(net, t.size());
  }
};

const Ring ring_family;
const TopologyRegistrar ring_topology_registrar{ring_family, 30};

}  // namespace
}  // namespace gcsim::machine::topologies
