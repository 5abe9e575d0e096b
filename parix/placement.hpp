#pragma once
// Which node each processor of a run is on (SimulationOptions::placement), checked the same way by
// every backend.
#include <vector>

namespace gcsim::parix {

// placement checked to be a permutation of 0..nodes-1 (else ParixError); identity when empty.
// A placement of more processors than nodes packs several onto a node (gcsim mpirun
// --ranks-per-node: they share its CPUs and memory, as a processor's threads do): then every node
// must hold at least one, and the run has placement.size() processors.
std::vector<int> checked_placement(const std::vector<int>& placement, int nodes);

}  // namespace gcsim::parix
