// Reduce-scatter. Pairwise (commutative ops): in round i this rank sends rank + i its block of the
// vector and folds rank - i's block for it into its own, n(n-1) messages in n-1 rounds.
// Reduce-then-scatter (any op, in rank order): a binomial reduce of the whole vector to rank 0,
// then a linear scatterv of its blocks.
#include <numeric>

#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

struct Blocks {
  std::vector<std::size_t> counts, offsets;  // elements
};

Blocks blocks_of(std::span<const std::size_t> counts) {
  Blocks b{{counts.begin(), counts.end()}, std::vector<std::size_t>(counts.size() + 1, 0)};
  std::partial_sum(counts.begin(), counts.end(), b.offsets.begin() + 1);
  return b;
}

void pairwise(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
              const Blocks& blocks, const Reduction& reduction) {
  const int n = call.channel.size(), r = call.channel.rank();
  const std::size_t es = reduction.element_size, mine = blocks.counts[static_cast<std::size_t>(r)];
  const auto block = [&](int rank) {
    return send.subspan(blocks.offsets[static_cast<std::size_t>(rank)] * es, blocks.counts[static_cast<std::size_t>(rank)] * es);
  };
  steps::copy(block(r), result);
  steps::Bytes theirs(mine * es);
  for (int step = 1; step < n; ++step) {
    const int to = (r + step) % n, from = (r - step + n) % n;
    steps::exchange(call, CollectivePhase::ReduceScatter, to, block(to), from, theirs);
    steps::combine(call, reduction, theirs.data(), result.data(), mine);
  }
}

void reduce_then_scatter(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                         const Blocks& blocks, const Reduction& reduction) {
  const std::size_t es = reduction.element_size, total = blocks.offsets.back();
  steps::Bytes whole(call.channel.rank() == 0 ? total * es : 0);
  reduce(call, send, whole, total, reduction, 0);
  std::vector<std::size_t> counts(blocks.counts.size()), displacements(blocks.counts.size());
  for (std::size_t i = 0; i < counts.size(); ++i) {
    counts[i] = blocks.counts[i] * es;
    displacements[i] = blocks.offsets[i] * es;
  }
  scatterv(call, whole, counts, displacements, result, 0);
}

}  // namespace

void reduce_scatter(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                    std::span<const std::size_t> counts, const Reduction& reduction, Algorithm algorithm) {
  const Blocks blocks = blocks_of(counts);
  if (blocks.offsets.back() == 0) return;
  const int n = call.channel.size();
  const MessageShape shape{.bytes = blocks.offsets.back() * reduction.element_size, .ranks = n,
                           .commutative = reduction.commutative, .count = blocks.offsets.back()};
  Algorithm chosen = resolve_algorithm(Collective::ReduceScatter, algorithm, shape);
  if (!reduction.commutative) chosen = Algorithm::ReduceThenScatter;
  if (chosen == Algorithm::Pairwise) return pairwise(call, send, result, blocks, reduction);
  reduce_then_scatter(call, send, result, blocks, reduction);
}

void reduce_scatter_block(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                          std::size_t count_per_rank, const Reduction& reduction, Algorithm algorithm) {
  const std::vector<std::size_t> counts(static_cast<std::size_t>(call.channel.size()), count_per_rank);
  reduce_scatter(call, send, result, counts, reduction, algorithm);
}

}  // namespace gcsim::mpi_layer
