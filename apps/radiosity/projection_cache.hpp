#pragma once
// Computation sampling for the simulated backend (as SMPI's): in a loop every replica projects
// every element for the same shooters, and the projection depends on the shooter alone. The first
// replica to need it computes it; the others take it and count its cost as their own, so every
// node's simulated time, message and result is what it would have been (tests), and the host does
// the work once instead of once per simulated node.
//
// One cache per simulation run, used by the replicas' fibers on one host thread (no locks). Under
// MPI each rank has its own, so nothing is shared that was not sent.
#include <map>
#include <memory>
#include <utility>

#include "apps/radiosity/hemicube.hpp"

namespace gcsim::radiosity {

class ProjectionCache {
 public:
  // Makes `renderer` hold the projection for `shooter` in loop `step`, computing it only if no
  // replica has yet. Loops run in step (each ends in an all-node exchange), so when any replica
  // asks for loop `step` every replica is done with earlier loops and their entries are dropped.
  void project(HemicubeRenderer& renderer, int step, int shooter, OpCounts& ops);

  // The replicas' shared samples-per-side table (HemicubeRenderer's memo).
  SamplesPerSideMemo& samples_per_side() { return samples_per_side_; }

  std::size_t entries() const { return entries_.size(); }
  std::int64_t computed() const { return computed_; }
  std::int64_t shared() const { return shared_; }

 private:
  std::map<std::pair<int, int>, std::shared_ptr<const HemicubeProjection>> entries_;  // (step, shooter)
  std::int64_t computed_ = 0, shared_ = 0;
  SamplesPerSideMemo samples_per_side_;
};

}  // namespace gcsim::radiosity
