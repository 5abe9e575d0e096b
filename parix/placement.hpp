#pragma once
// Which node each processor of a run is on (SimulationOptions::placement), checked the same way by
// every backend.
#include <vector>

namespace gcsim::parix {

// placement checked to be a permutation of 0..nodes-1 (else ParixError); identity when empty.
std::vector<int> checked_placement(const std::vector<int>& placement, int nodes);

}  // namespace gcsim::parix
