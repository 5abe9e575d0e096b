#pragma once
// The topology families gcsim ships, each defined in this folder (mesh and torus in
// grid_topology.cpp); topology_families() in machine/topology.cpp lists them.
#include "machine/topology.hpp"

namespace gcsim::machine::topologies {

const TopologyFamily& mesh();
const TopologyFamily& torus();
const TopologyFamily& ring();
const TopologyFamily& binary_tree();
const TopologyFamily& hypercube();

}  // namespace gcsim::machine::topologies
