// Broadcast: a binomial tree (n-1 messages, ceil(log2 n) rounds), or for long messages van de
// Geijn's binomial scatter of n pieces followed by a ring allgather of them, which moves about
// 2 * bytes through each rank instead of bytes * log2 n through the root.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

using steps::absolute_rank;

// Children of relative rank rel are rel + mask for the masks below its lowest set bit.
int binomial_parent_mask(int rel, int n) {
  int mask = 1;
  while (mask < n && (rel & mask) == 0) mask *= 2;
  return mask;  // rel's lowest set bit, or the first power of two >= n for the root
}

void binomial(const CollectiveCall& call, std::span<std::byte> buffer, int root) {
  const int n = call.channel.size(), rel = steps::relative_rank(call.channel.rank(), root, n);
  const int mask = binomial_parent_mask(rel, n);
  if (rel != 0) steps::recv(call, CollectivePhase::BcastTree, absolute_rank(rel - mask, root, n), buffer);
  for (int child = mask / 2; child > 0; child /= 2)
    if (rel + child < n) steps::send(call, CollectivePhase::BcastTree, absolute_rank(rel + child, root, n), buffer);
}

// Piece i (of relative rank i) is bytes [offsets[i], offsets[i+1]); a subtree of relative ranks
// [first, last) holds bytes [offsets[first], offsets[last]).
std::span<std::byte> pieces(std::span<std::byte> buffer, const std::vector<std::size_t>& offsets, int first, int last) {
  return buffer.subspan(offsets[static_cast<std::size_t>(first)],
                        offsets[static_cast<std::size_t>(last)] - offsets[static_cast<std::size_t>(first)]);
}

void scatter_pieces(const CollectiveCall& call, std::span<std::byte> buffer, int root,
                    const std::vector<std::size_t>& offsets) {
  const int n = call.channel.size(), rel = steps::relative_rank(call.channel.rank(), root, n);
  const int mask = binomial_parent_mask(rel, n);
  if (rel != 0)
    steps::recv(call, CollectivePhase::BcastScatter, absolute_rank(rel - mask, root, n),
                pieces(buffer, offsets, rel, std::min(rel + mask, n)));
  for (int child = mask / 2; child > 0; child /= 2)
    if (rel + child < n)
      steps::send(call, CollectivePhase::BcastScatter, absolute_rank(rel + child, root, n),
                  pieces(buffer, offsets, rel + child, std::min(rel + 2 * child, n)));
}

void ring_allgather_pieces(const CollectiveCall& call, std::span<std::byte> buffer, int root,
                           const std::vector<std::size_t>& offsets) {
  const int n = call.channel.size(), r = call.channel.rank(), rel = steps::relative_rank(r, root, n);
  for (int step = 0; step < n - 1; ++step) {
    const int out = (rel - step + n) % n, in = (rel - step - 1 + n) % n;
    steps::exchange(call, CollectivePhase::BcastAllgather, (r + 1) % n, pieces(buffer, offsets, out, out + 1),
                    (r - 1 + n) % n, pieces(buffer, offsets, in, in + 1));
  }
}

}  // namespace

void bcast(const CollectiveCall& call, std::span<std::byte> buffer, int root, Algorithm algorithm) {
  const int n = call.channel.size();
  if (n == 1 || buffer.empty()) return;
  const Algorithm chosen = resolve_algorithm(Collective::Bcast, algorithm, {.bytes = buffer.size(), .ranks = n});
  if (chosen == Algorithm::ScatterAllgather) {
    const std::vector<std::size_t> offsets = steps::split_evenly(buffer.size(), n);
    scatter_pieces(call, buffer, root, offsets);
    ring_allgather_pieces(call, buffer, root, offsets);
    return;
  }
  binomial(call, buffer, root);
}

}  // namespace gcsim::mpi_layer
