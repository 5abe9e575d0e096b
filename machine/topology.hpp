#pragma once
// Virtual topologies (mesh, torus, ring, binary tree, hypercube): their graphs, the thesis's
// interconnect parameters computed exactly on those graphs (table 2.1), the thesis's formulas for
// comparison, and a mapping onto the physical interconnect with its dilation and congestion.
//
// Each topology is one small TopologyFamily class in a file of machine/topologies/ that registers
// it with a TopologyRegistrar; everything here works on any registered family.
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

#include "machine/interconnect.hpp"

namespace gcsim::machine {

class TopologyFamily;

// A registered topology's name ("mesh", "torus", "ring", "tree", "hypercube").
using TopologyKind = std::string_view;
// The registered name equal to s; throws std::invalid_argument listing the names.
TopologyKind parse_topology_kind(std::string_view s);
inline std::string_view to_string(TopologyKind k) { return k; }

struct VirtualTopology {
  TopologyKind kind;
  int width = 0;   // grids (mesh, torus): the virtual grid (the GC shape for n)
  int height = 0;
  std::vector<std::vector<int>> neighbours;  // sorted, no duplicates
  int size() const { return static_cast<int>(neighbours.size()); }

  // For families building the graph: an undirected edge (self-loops ignored), then finish().
  void add_edge(int a, int b);
  void finish();  // sorts each neighbour list and drops duplicates
};

struct TopologyMetrics {
  double D = 0, d = 0, R = 0, r = 0, k = 0, B = 0;
};

// One kind of virtual topology: its graph on n processors, where it places each processor on the
// physical interconnect, and the thesis's closed forms for its parameters.
class TopologyFamily {
 public:
  virtual ~TopologyFamily() = default;
  virtual std::string_view name() const = 0;
  // Throws std::invalid_argument for sizes the topology cannot take (hypercube: a power of two).
  virtual VirtualTopology graph(int n) const = 0;
  // node_of[v]: the physical node of virtual processor v (t has at most net.nodes() processors),
  // laid out by the interconnect's coordinates (Interconnect::width, height, node_at).
  virtual std::vector<int> placement(const VirtualTopology& t, const Interconnect& net) const = 0;
  // The thesis's table 2.1 formulas; NaN where the thesis gives none.
  virtual TopologyMetrics thesis_formulas(int n) const;
};

// Adds a family when its file is linked: a namespace-scope constant beside the family's class,
//   const TopologyRegistrar ring_registrar{ring_family, 30};
// which must outlive the program's runs (a namespace-scope object of the same file does). Help
// texts list families by order, then name: mesh 10, torus 20, ring 30, tree 40, hypercube 50.
struct TopologyRegistrar {
  TopologyRegistrar(const TopologyFamily& family, int order = 100);
};

// The registered families, in the order help texts list them.
std::vector<const TopologyFamily*> topology_families();
std::vector<std::string> topology_names();
// "mesh, torus, ring, tree, hypercube": for error messages.
std::string topology_name_list();
// Throws std::invalid_argument listing the names if none is registered under name.
const TopologyFamily& topology_family(std::string_view name);

// Throws std::invalid_argument for unknown names and sizes the topology cannot take.
VirtualTopology make_topology(TopologyKind kind, int n);
TopologyMetrics exact_metrics(const VirtualTopology& t);
TopologyMetrics thesis_formulas(TopologyKind kind, int n);

struct PhysicalMapping {
  std::vector<int> node_of;  // virtual processor -> physical node
  int dilation = 0;          // longest physical route of a virtual edge, in hops
  double mean_dilation = 0;
  int congestion = 0;        // most virtual edges (each direction) sharing one physical channel
};
// Maps t onto the interconnect by its family's placement (on the GC's mesh: meshes as they are,
// tori folded so wrap edges stay short, rings along a Hamiltonian cycle where one exists, trees in
// breadth-first order, hypercubes with the low address bits along x and the high bits along y)
// and measures it on the interconnect's routes.
PhysicalMapping map_onto(const VirtualTopology& t, const Interconnect& net);

}  // namespace gcsim::machine
