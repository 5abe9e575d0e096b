#pragma once
// Virtual topologies from a processor's point of view: its neighbours in a ring, binary tree, mesh,
// torus or hypercube over all count() processors (machine/topology.hpp has the graphs), and the
// placement that puts each virtual processor on the physical node its topology maps it to.
//
//   auto ring = parix::virtual_topology(p, "ring");
//   for (int peer : ring.neighbours()) ...
//
//   SimulationOptions o;
//   o.placement = parix::topology_placement(o.config, "torus");  // processor i on node_of[i]
#include <string_view>
#include <vector>

#include "machine/machine_config.hpp"
#include "machine/topology.hpp"
#include "parix/processor.hpp"

namespace gcsim::parix {

class VirtualTopologyView {
 public:
  VirtualTopologyView(machine::VirtualTopology graph, int me) : graph_(std::move(graph)), me_(me) {}
  std::string_view name() const { return graph_.kind; }
  int size() const { return graph_.size(); }
  int me() const { return me_; }
  // This processor's neighbours, ascending. Copies, so that the chained
  // `virtual_topology(p, "ring").neighbours()` stays valid in a range-for.
  std::vector<int> neighbours() const { return graph_.neighbours[me_]; }
  std::vector<int> neighbours(int processor) const { return graph_.neighbours.at(processor); }
  const machine::VirtualTopology& graph() const { return graph_; }

 private:
  machine::VirtualTopology graph_;
  int me_;
};

// The named topology over p.count() processors, seen from p. Throws ParixError for an unknown
// name or a size the topology cannot take (a hypercube needs a power of two).
VirtualTopologyView virtual_topology(const Processor& p, std::string_view name);

// For SimulationOptions::placement: where the named topology on `nodes` processors (0: all of
// the config's) puts each processor on the config's interconnect (machine::map_onto).
std::vector<int> topology_placement(const machine::MachineConfig& config, std::string_view name, int nodes = 0);

}  // namespace gcsim::parix
