// Reduce-scatter. Pairwise (commutative ops): in round i this rank sends rank + i its block of the
// vector and folds rank - i's block for it into its own, n(n-1) messages in n-1 rounds.
// Recursive halving (commutative ops, MPICH's for short vectors): ranks fold to a power of two p
// as allreduce's recursive doubling does, then in log2 p rounds each hands the partner at
// distance p/2, p/4, ... the half of its remaining blocks that the partner keeps, and the odd
// ranks of the fold finally pass their even neighbours' blocks back.
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

// After the fold, new rank i stands for ranks 2i and 2i+1 (i < rem) or i + rem, and their blocks.
struct FoldedBlocks {
  int pof2, rem, new_rank;  // new_rank -1: handed its vector on
  std::vector<std::size_t> offsets;  // elements: new rank i's blocks are [offsets[i], offsets[i+1])
  int real_rank(int peer) const { return peer < rem ? peer * 2 + 1 : peer + rem; }
};

FoldedBlocks fold_blocks(int n, int r, const Blocks& blocks) {
  const int pof2 = steps::largest_power_of_two_at_most(n), rem = n - pof2;
  FoldedBlocks f{pof2, rem, r < 2 * rem ? (r % 2 == 0 ? -1 : r / 2) : r - rem, {}};
  for (int i = 0; i < pof2; ++i) f.offsets.push_back(blocks.offsets[static_cast<std::size_t>(i < rem ? 2 * i : i + rem)]);
  f.offsets.push_back(blocks.offsets.back());
  return f;
}

void recursive_halving(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                       const Blocks& blocks, const Reduction& reduction) {
  using Phase = CollectivePhase;
  const int n = call.channel.size(), r = call.channel.rank();
  const std::size_t es = reduction.element_size, total = blocks.offsets.back();
  const FoldedBlocks f = fold_blocks(n, r, blocks);
  steps::Bytes acc(send.begin(), send.end()), theirs(acc.size());
  const auto range = [&](steps::Bytes& v, int first, int last) {
    const std::size_t a = f.offsets[static_cast<std::size_t>(first)], b = f.offsets[static_cast<std::size_t>(last)];
    return std::span(v).subspan(a * es, (b - a) * es);
  };
  if (f.new_rank == -1) steps::send(call, Phase::ReduceScatterFold, r + 1, acc);
  if (r < 2 * f.rem && r % 2 == 1) {
    steps::recv(call, Phase::ReduceScatterFold, r - 1, theirs);
    steps::combine(call, reduction, theirs.data(), acc.data(), total);
  }
  if (f.new_rank >= 0) {
    int first = 0, last = f.pof2;
    for (int mask = f.pof2 / 2; mask > 0; mask /= 2) {
      const int peer = f.new_rank ^ mask, middle = first + mask;
      const bool keep_low = f.new_rank < peer;
      const int keep_first = keep_low ? first : middle, keep_last = keep_low ? middle : last;
      steps::exchange(call, Phase::ReduceScatterHalving, f.real_rank(peer),
                      keep_low ? range(acc, middle, last) : range(acc, first, middle), f.real_rank(peer),
                      range(theirs, keep_first, keep_last));
      steps::combine(call, reduction, range(theirs, keep_first, keep_last).data(),
                     range(acc, keep_first, keep_last).data(), f.offsets[static_cast<std::size_t>(keep_last)] -
                                                                    f.offsets[static_cast<std::size_t>(keep_first)]);
      first = keep_first;
      last = keep_last;
    }
  }
  const auto own = [&](int rank) {
    return std::span(acc).subspan(blocks.offsets[static_cast<std::size_t>(rank)] * es,
                                  blocks.counts[static_cast<std::size_t>(rank)] * es);
  };
  if (f.new_rank == -1) steps::recv(call, Phase::ReduceScatterUnfold, r + 1, result);
  else steps::copy(own(r), result);
  if (r < 2 * f.rem && r % 2 == 1) steps::send(call, Phase::ReduceScatterUnfold, r - 1, own(r - 1));
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
  if (chosen == Algorithm::RecursiveHalving) return recursive_halving(call, send, result, blocks, reduction);
  reduce_then_scatter(call, send, result, blocks, reduction);
}

void reduce_scatter_block(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                          std::size_t count_per_rank, const Reduction& reduction, Algorithm algorithm) {
  const std::vector<std::size_t> counts(static_cast<std::size_t>(call.channel.size()), count_per_rank);
  reduce_scatter(call, send, result, counts, reduction, algorithm);
}

}  // namespace gcsim::mpi_layer
