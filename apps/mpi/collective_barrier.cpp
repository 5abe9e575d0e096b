// Barrier by dissemination (Hensgen, Finkel and Manber 1988): in round k every rank signals rank
// + 2^k and waits for rank - 2^k, so after ceil(log2 n) rounds each has heard, directly or not,
// from all others. n * ceil(log2 n) empty messages.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {

void barrier(const CollectiveCall& call, Algorithm algorithm) {
  const int n = call.channel.size(), r = call.channel.rank();
  resolve_algorithm(Collective::Barrier, algorithm, {.ranks = n});  // only checks the name
  for (int distance = 1; distance < n; distance *= 2)
    steps::exchange(call, CollectivePhase::Barrier, (r + distance) % n, {}, (r - distance + n) % n, {});
}

}  // namespace gcsim::mpi_layer
