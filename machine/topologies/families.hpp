#pragma once
// The topology families gcsim ships; machine/topology_registry.cpp lists them by name.
#include "machine/topology.hpp"

namespace gcsim::machine::topologies {

const TopologyFamily& mesh();
const TopologyFamily& torus();
const TopologyFamily& ring();
const TopologyFamily& binary_tree();
const TopologyFamily& hypercube();

}  // namespace gcsim::machine::topologies
