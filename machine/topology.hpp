#pragma once
// Virtual topologies (mesh, torus, ring, binary tree, hypercube): their graphs, the thesis's
// interconnect parameters computed exactly on those graphs (table 2.1), the thesis's formulas for
// comparison, and a mapping onto the physical mesh with its dilation and congestion.
//
// Definitions (thesis 2.3): the processor distance of two PEs is the number of relays on a shortest
// path plus one, i.e. the hop count. D = maximum and d = mean distance over ordered pairs of
// distinct PEs. The relay load of a PE is the number of shortest paths between pairs of other PEs
// that pass through it; where a pair has several shortest paths each counts by its share
// (betweenness over unordered pairs). R = maximum, r = mean relay load. k = mean degree.
// B = broadcast distance: transfer steps until data sent by the managing PE reaches every PE; we
// place the manager where that is smallest, so B is the graph's radius.
#include <string>
#include <string_view>
#include <vector>

#include "machine/mesh.hpp"

namespace gcsim::machine {

enum class TopologyKind { mesh, torus, ring, tree, hypercube };
inline constexpr std::string_view kTopologyNames = "mesh, torus, ring, tree, hypercube";
TopologyKind parse_topology_kind(std::string_view s);  // throws std::invalid_argument
std::string_view to_string(TopologyKind k);

struct VirtualTopology {
  TopologyKind kind;
  int width = 0;   // mesh and torus: the virtual grid (the GC shape for n)
  int height = 0;
  std::vector<std::vector<int>> neighbours;  // sorted, no duplicates
  int size() const { return static_cast<int>(neighbours.size()); }
};
// Throws std::invalid_argument for sizes the topology cannot take (hypercube: a power of two).
VirtualTopology make_topology(TopologyKind kind, int n);

struct TopologyMetrics {
  double D = 0, d = 0, R = 0, r = 0, k = 0, B = 0;
};
TopologyMetrics exact_metrics(const VirtualTopology& t);
// The thesis's table 2.1 formulas; NaN where the thesis gives none (torus, ring).
TopologyMetrics thesis_formulas(TopologyKind kind, int n);

struct MeshMapping {
  std::vector<int> node_of;  // virtual processor -> physical node
  int dilation = 0;          // longest physical route of a virtual edge, in hops
  double mean_dilation = 0;
  int congestion = 0;        // most virtual edges (each direction) sharing one physical channel
};
// Maps t onto the mesh: meshes as they are, tori folded (wrap edges stay short), rings along a
// Hamiltonian cycle of the mesh where one exists, trees in breadth-first order, hypercubes with
// the low address bits along x and the high bits along y.
MeshMapping map_onto_mesh(const VirtualTopology& t, const Mesh& mesh);

}  // namespace gcsim::machine
