// Mesh and torus: a virtual grid in the GC's shape for n (machine_config.hpp gc_mesh_shape).
#include <cmath>

#include "machine/machine_config.hpp"
#include "machine/topology.hpp"

namespace gcsim::machine::topologies {
namespace {

// Position i of a ring of length len folded so that neighbours, including the wrap, are <= 2 apart.
int fold(int i, int len) { return i < (len + 1) / 2 ? 2 * i : 2 * (len - 1 - i) + 1; }

class Grid final : public TopologyFamily {
 public:
  explicit Grid(bool wraps) : wraps_(wraps) {}
  std::string_view name() const override { return wraps_ ? "torus" : "mesh"; }

  VirtualTopology graph(int n) const override {
    const MeshShape s = gc_mesh_shape(n);
    VirtualTopology t{name(), s.width, s.height, std::vector<std::vector<int>>(n)};
    for (int y = 0; y < s.height; ++y) {
      for (int x = 0; x < s.width; ++x) {
        const int v = y * s.width + x;
        if (x + 1 < s.width) t.add_edge(v, v + 1);
        if (y + 1 < s.height) t.add_edge(v, v + s.width);
        if (wraps_) {
          if (x == s.width - 1 && s.width > 2) t.add_edge(v, y * s.width);
          if (y == s.height - 1 && s.height > 2) t.add_edge(v, x);
        }
      }
    }
    t.finish();
    return t;
  }

  // Meshes as they are; tori folded so that wrap edges stay short.
  std::vector<int> placement(const VirtualTopology& t, const Interconnect& net) const override {
    std::vector<int> node_of(t.size());
    for (int v = 0; v < t.size(); ++v) {
      int x = v % t.width, y = v / t.width;
      if (wraps_) {
        x = fold(x, t.width);
        y = fold(y, t.height);
      }
      if (t.width <= net.width() && t.height <= net.height()) node_of[v] = net.node_at(x, y);
      else node_of[v] = net.node_at(y, x);  // the virtual grid is the turned physical one
    }
    return node_of;
  }

  // Eqs. 2.1-2.6 for the mesh; the thesis gives none for the torus.
  TopologyMetrics thesis_formulas(int n) const override {
    if (wraps_) return TopologyFamily::thesis_formulas(n);
    const double N = n;
    return {2 * std::sqrt(N), 2.0 / 3.0 * std::sqrt(N), std::sqrt(N * N * N) / 2, std::sqrt(N * N * N) / 3, 4, std::sqrt(N)};
  }

 private:
  bool wraps_;
};

const Grid mesh_family(false);
const Grid torus_family(true);
const TopologyRegistrar mesh_topology_registrar{mesh_family, 10};
const TopologyRegistrar torus_topology_registrar{torus_family, 20};

}  // namespace
}  // namespace gcsim::machine::topologies
