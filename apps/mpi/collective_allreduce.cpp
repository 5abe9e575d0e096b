// Allreduce three ways. Recursive doubling (n log2 n messages on a power of two): ranks exchange
// their whole vectors with the partner at distance 1, 2, 4, ...; a rank count that is not a power
// of two is first folded (the first 2 * rem ranks pair up, each even one hands its vector to the
// odd one above it and waits) and unfolded at the end. Rabenseifner: on the folded ranks a
// recursive-halving reduce-scatter and a recursive-doubling allgather, about 2 * bytes per rank.
// Ring: a ring reduce-scatter and a ring allgather of n pieces, 2(n-1) rounds.
// On folded ranks every active rank holds the partial of consecutive ranks, blocks ordered by
// their new rank, and combines with the lower block as `in`: a non-commutative op keeps its order.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

using Phase = CollectivePhase;

// The power-of-two set of active ranks after folding.
struct Fold {
  int pof2, rem, new_rank;  // new_rank -1: handed its vector on
  int real_rank(int new_rank_of_peer) const {
    return new_rank_of_peer < rem ? new_rank_of_peer * 2 + 1 : new_rank_of_peer + rem;
  }
};

Fold fold_in(const CollectiveCall& call, steps::Bytes& acc, std::size_t count, const Reduction& reduction) {
  const int n = call.channel.size(), r = call.channel.rank();
  const int pof2 = steps::largest_power_of_two_at_most(n), rem = n - pof2;
  if (r >= 2 * rem) return {pof2, rem, r - rem};
  if (r % 2 == 0) {
    steps::send(call, Phase::AllreduceFold, r + 1, acc);
    return {pof2, rem, -1};
  }
  steps::Bytes lower(acc.size());
  steps::recv(call, Phase::AllreduceFold, r - 1, lower);
  steps::combine(call, reduction, lower.data(), acc.data(), count);
  return {pof2, rem, r / 2};
}

void fold_out(const CollectiveCall& call, const Fold& fold, std::span<std::byte> result) {
  const int r = call.channel.rank();
  if (r >= 2 * fold.rem) return;
  if (r % 2 == 0) steps::recv(call, Phase::AllreduceUnfold, r + 1, result);
  else steps::send(call, Phase::AllreduceUnfold, r - 1, result);
}

// mine = theirs op mine when the peer's block is lower, else mine = mine op theirs.
void combine_ordered(const CollectiveCall& call, const Reduction& reduction, bool peer_is_lower,
                     std::span<std::byte> mine, std::span<std::byte> theirs, std::size_t count) {
  if (peer_is_lower || reduction.commutative) return steps::combine(call, reduction, theirs.data(), mine.data(), count);
  steps::combine(call, reduction, mine.data(), theirs.data(), count);
  steps::copy(theirs, mine);
}

void recursive_doubling(const CollectiveCall& call, steps::Bytes& acc, std::size_t count, const Reduction& reduction,
                        const Fold& fold) {
  steps::Bytes theirs(acc.size());
  for (int mask = 1; mask < fold.pof2; mask *= 2) {
    const int peer = fold.new_rank ^ mask;
    steps::exchange(call, Phase::AllreduceExchange, fold.real_rank(peer), acc, fold.real_rank(peer), theirs);
    combine_ordered(call, reduction, peer < fold.new_rank, acc, theirs, count);
  }
}

// Rabenseifner on the folded ranks: piece i of pof2 is elements [offsets[i], offsets[i+1]).
struct Pieces {
  std::vector<std::size_t> offsets;
  std::size_t element_size;
  std::span<std::byte> of(std::span<std::byte> v, int first, int last) const {
    const std::size_t a = offsets[static_cast<std::size_t>(first)], b = offsets[static_cast<std::size_t>(last)];
    return v.subspan(a * element_size, (b - a) * element_size);
  }
  std::size_t count(int first, int last) const {
    return offsets[static_cast<std::size_t>(last)] - offsets[static_cast<std::size_t>(first)];
  }
};

// Halves the range of pieces this rank keeps each step; returns the one piece it ends with.
int recursive_halving(const CollectiveCall& call, steps::Bytes& acc, const Pieces& pieces, const Reduction& reduction,
                      const Fold& fold) {
  steps::Bytes theirs(acc.size());
  int first = 0, last = fold.pof2;
  for (int mask = 1; mask < fold.pof2; mask *= 2) {  // partners' blocks stay adjacent
    const int peer = fold.new_rank ^ mask, middle = first + (last - first) / 2;
    const bool keep_low = fold.new_rank < peer;
    const int keep_first = keep_low ? first : middle, keep_last = keep_low ? middle : last;
    const int give_first = keep_low ? middle : first, give_last = keep_low ? last : middle;
    steps::exchange(call, Phase::RabenseifnerHalving, fold.real_rank(peer), pieces.of(acc, give_first, give_last),
                    fold.real_rank(peer), pieces.of(theirs, keep_first, keep_last));
    combine_ordered(call, reduction, peer < fold.new_rank, pieces.of(acc, keep_first, keep_last),
                    pieces.of(theirs, keep_first, keep_last), pieces.count(keep_first, keep_last));
    first = keep_first;
    last = keep_last;
  }
  return first;
}

void recursive_doubling_gather(const CollectiveCall& call, steps::Bytes& acc, const Pieces& pieces, const Fold& fold,
                               int mine) {
  int first = mine, last = mine + 1;
  for (int mask = fold.pof2 / 2; mask >= 1; mask /= 2) {  // the halving's steps backwards
    const int peer = fold.new_rank ^ mask;
    const bool have_low = fold.new_rank < peer;
    const int peer_first = have_low ? last : first - (last - first), peer_last = have_low ? last + (last - first) : first;
    steps::exchange(call, Phase::RabenseifnerDoubling, fold.real_rank(peer), pieces.of(acc, first, last),
                    fold.real_rank(peer), pieces.of(acc, peer_first, peer_last));
    first = std::min(first, peer_first);
    last = std::max(last, peer_last);
  }
}

void ring(const CollectiveCall& call, steps::Bytes& acc, std::size_t count, const Reduction& reduction) {
  const int n = call.channel.size(), r = call.channel.rank();
  const Pieces pieces{steps::split_evenly(count, n), reduction.element_size};
  steps::Bytes theirs(acc.size());
  const int right = (r + 1) % n, left = (r - 1 + n) % n;
  for (int step = 0; step < n - 1; ++step) {  // after it, piece r + 1 is complete here
    const int out = (r - step + n) % n, in = (r - step - 1 + n) % n;
    steps::exchange(call, Phase::AllreduceRingScatter, right, pieces.of(acc, out, out + 1), left,
                    pieces.of(theirs, in, in + 1));
    steps::combine(call, reduction, pieces.of(theirs, in, in + 1).data(), pieces.of(acc, in, in + 1).data(),
                   pieces.count(in, in + 1));
  }
  for (int step = 0; step < n - 1; ++step) {
    const int out = (r + 1 - step + n) % n, in = (r - step + n) % n;
    steps::exchange(call, Phase::AllreduceRingGather, right, pieces.of(acc, out, out + 1), left,
                    pieces.of(acc, in, in + 1));
  }
}

Algorithm applicable(Algorithm chosen, std::size_t count, const Reduction& reduction, int n) {
  if (chosen == Algorithm::Ring && !reduction.commutative) return Algorithm::RecursiveDoubling;
  if (chosen == Algorithm::Rabenseifner && count < static_cast<std::size_t>(steps::largest_power_of_two_at_most(n)))
    return Algorithm::RecursiveDoubling;
  return chosen;
}

}  // namespace

void allreduce(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
               std::size_t count, const Reduction& reduction, Algorithm algorithm) {
  const int n = call.channel.size();
  steps::copy(send, result);
  if (n == 1 || count == 0) return;
  const MessageShape shape{.bytes = count * reduction.element_size, .ranks = n,
                           .commutative = reduction.commutative, .count = count};
  const Algorithm chosen =
      applicable(resolve_algorithm(Collective::Allreduce, algorithm, shape), count, reduction, n);
  steps::Bytes acc(result.begin(), result.end());
  if (chosen == Algorithm::Ring) {
    ring(call, acc, count, reduction);
    return steps::copy(acc, result);
  }
  const Fold fold = fold_in(call, acc, count, reduction);
  if (fold.new_rank >= 0) {
    if (chosen == Algorithm::Rabenseifner) {
      const Pieces pieces{steps::split_evenly(count, fold.pof2), reduction.element_size};
      const int mine = recursive_halving(call, acc, pieces, reduction, fold);
      recursive_doubling_gather(call, acc, pieces, fold, mine);
    } else {
      recursive_doubling(call, acc, count, reduction, fold);
    }
    steps::copy(acc, result);
  }
  fold_out(call, fold, result);
}

}  // namespace gcsim::mpi_layer
