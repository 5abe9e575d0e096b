// Allgather(v). Every algorithm works on a scratch copy of the blocks packed in rank order (or, for
// Bruck, in order starting at this rank) and copies them to their displacements at the end.
// Ring: n-1 rounds, each rank passes on the block it received last, n(n-1) messages. Recursive
// doubling (a power of two): the partner at distance 1, 2, 4, ... gets every block this rank has,
// n log2 n messages. Bruck (Bruck et al. 1997): in round k this rank sends the first min(2^k,
// n - 2^k) blocks it has to rank - 2^k, ceil(log2 n) rounds for any n.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

using Phase = CollectivePhase;

// Every rank's block packed one after the other, in rank order starting at first_rank.
class PackedBlocks {
 public:
  PackedBlocks(std::span<const std::size_t> counts, int first_rank) : counts_(counts), first_(first_rank) {
    offsets_.assign(counts.size() + 1, 0);
    for (std::size_t i = 0; i < counts.size(); ++i) offsets_[i + 1] = offsets_[i] + counts[rank_at(i)];
    bytes_.resize(offsets_.back());
  }
  // Blocks at positions [first, last) of the packing.
  std::span<std::byte> at(std::size_t first, std::size_t last) {
    return std::span(bytes_).subspan(offsets_[first], offsets_[last] - offsets_[first]);
  }
  std::span<std::byte> of_rank(int rank) {
    const std::size_t i = position_of(rank);
    return at(i, i + 1);
  }
  std::size_t position_of(int rank) const {
    return static_cast<std::size_t>((rank - first_ + static_cast<int>(counts_.size())) % static_cast<int>(counts_.size()));
  }
  std::size_t rank_at(std::size_t position) const { return (position + static_cast<std::size_t>(first_)) % counts_.size(); }

 private:
  std::span<const std::size_t> counts_;
  int first_;
  std::vector<std::size_t> offsets_;
  steps::Bytes bytes_;
};

void ring(const CollectiveCall& call, PackedBlocks& blocks) {
  const int n = call.channel.size(), r = call.channel.rank();
  for (int step = 0; step < n - 1; ++step) {
    const int out = (r - step + n) % n, in = (r - step - 1 + n) % n;
    steps::exchange(call, Phase::Allgather, (r + 1) % n, blocks.of_rank(out), (r - 1 + n) % n, blocks.of_rank(in));
  }
}

void recursive_doubling(const CollectiveCall& call, PackedBlocks& blocks) {
  const int n = call.channel.size(), r = call.channel.rank();
  for (int mask = 1; mask < n; mask *= 2) {
    const int peer = r ^ mask;
    const auto mine = static_cast<std::size_t>(r & ~(mask - 1)), theirs = static_cast<std::size_t>(peer & ~(mask - 1));
    const auto width = static_cast<std::size_t>(mask);
    steps::exchange(call, Phase::Allgather, peer, blocks.at(mine, mine + width), peer,
                    blocks.at(theirs, theirs + width));
  }
}

// blocks are packed starting at this rank: position i holds rank r + i.
void bruck(const CollectiveCall& call, PackedBlocks& blocks) {
  const int n = call.channel.size(), r = call.channel.rank();
  for (int have = 1; have < n; have *= 2) {
    const auto moved = static_cast<std::size_t>(std::min(have, n - have)), at = static_cast<std::size_t>(have);
    steps::exchange(call, Phase::Allgather, (r - have + n) % n, blocks.at(0, moved), (r + have) % n,
                    blocks.at(at, at + moved));
  }
}

Algorithm applicable(Algorithm chosen, int n) {
  return chosen == Algorithm::RecursiveDoubling && !steps::is_power_of_two(n) ? Algorithm::Bruck : chosen;
}

}  // namespace

void allgatherv(const CollectiveCall& call, std::span<std::byte> result, std::span<const std::size_t> counts,
                std::span<const std::size_t> displacements, Algorithm algorithm) {
  const int n = call.channel.size(), r = call.channel.rank();
  std::size_t total = 0;
  for (std::size_t c : counts) total += c;
  if (n == 1 || total == 0) return;
  const Algorithm chosen = applicable(resolve_algorithm(Collective::Allgatherv, algorithm, {.bytes = total, .ranks = n}), n);
  PackedBlocks blocks(counts, chosen == Algorithm::Bruck ? r : 0);
  const auto placed = [&](int rank) {
    return result.subspan(displacements[static_cast<std::size_t>(rank)], counts[static_cast<std::size_t>(rank)]);
  };
  steps::copy(placed(r), blocks.of_rank(r));
  if (chosen == Algorithm::Bruck) bruck(call, blocks);
  else if (chosen == Algorithm::RecursiveDoubling) recursive_doubling(call, blocks);
  else ring(call, blocks);
  for (int rank = 0; rank < n; ++rank)
    if (rank != r) steps::copy(blocks.of_rank(rank), placed(rank));
}

void allgather(const CollectiveCall& call, std::span<std::byte> result, std::size_t block, Algorithm algorithm) {
  const auto n = static_cast<std::size_t>(call.channel.size());
  const std::vector<std::size_t> counts(n, block);
  std::vector<std::size_t> displacements(n);
  for (std::size_t i = 0; i < n; ++i) displacements[i] = i * block;
  allgatherv(call, result, counts, displacements, algorithm);
}

}  // namespace gcsim::mpi_layer
