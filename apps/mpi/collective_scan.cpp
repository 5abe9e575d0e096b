// Inclusive and exclusive prefix reductions. Recursive doubling (MPICH's): ranks exchange a partial
// reduction of a growing block of consecutive ranks with the partner at distance 1, 2, 4, ...,
// ceil(log2 n) rounds; a rank folds into its result only what comes from below. Linear: a chain,
// rank r waits for the prefix of ranks 0..r-1, n-1 messages in n-1 rounds.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

using Phase = CollectivePhase;

// partial: the reduction of this rank's block of 2^k ranks. On return result is the inclusive or
// exclusive prefix (has_result false: nothing came from below, the exclusive result is unset).
void recursive_doubling(const CollectiveCall& call, steps::Bytes& partial, std::span<std::byte> result,
                        std::size_t count, const Reduction& reduction, bool inclusive, Phase phase) {
  const int n = call.channel.size(), r = call.channel.rank();
  steps::Bytes theirs(partial.size());
  bool has_result = inclusive;
  for (int mask = 1; mask < n; mask *= 2) {
    const int peer = r ^ mask;
    if (peer >= n) continue;
    steps::exchange(call, phase, peer, partial, peer, theirs);
    if (peer < r) {  // theirs covers the ranks just below partial's
      steps::combine(call, reduction, theirs.data(), partial.data(), count);
      if (has_result) steps::combine(call, reduction, theirs.data(), result.data(), count);
      else steps::copy(theirs, result);
      has_result = true;
    } else if (reduction.commutative) {
      steps::combine(call, reduction, theirs.data(), partial.data(), count);
    } else {
      steps::combine(call, reduction, partial.data(), theirs.data(), count);
      partial.swap(theirs);
    }
  }
}

void linear(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
            std::size_t count, const Reduction& reduction, bool inclusive, Phase phase) {
  const int n = call.channel.size(), r = call.channel.rank();
  steps::Bytes below(send.size()), onward(send.begin(), send.end());
  if (r > 0) {
    steps::recv(call, phase, r - 1, below);
    steps::combine(call, reduction, below.data(), onward.data(), count);
    steps::copy(inclusive ? std::span<const std::byte>(onward) : std::span<const std::byte>(below), result);
  } else if (inclusive) {
    steps::copy(send, result);
  }
  if (r + 1 < n) steps::send(call, phase, r + 1, onward);
}

void prefix(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
            std::size_t count, const Reduction& reduction, Algorithm algorithm, bool inclusive) {
  if (count == 0) return;
  const Collective c = inclusive ? Collective::Scan : Collective::Exscan;
  const Phase phase = inclusive ? Phase::Scan : Phase::Exscan;
  const MessageShape shape{.bytes = count * reduction.element_size, .ranks = call.channel.size(),
                           .commutative = reduction.commutative, .count = count};
  if (resolve_algorithm(c, algorithm, shape) == Algorithm::Linear)
    return linear(call, send, result, count, reduction, inclusive, phase);
  if (inclusive) steps::copy(send, result);
  steps::Bytes partial(send.begin(), send.end());
  recursive_doubling(call, partial, result, count, reduction, inclusive, phase);
}

}  // namespace

void scan(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, std::size_t count,
          const Reduction& reduction, Algorithm algorithm) {
  prefix(call, send, result, count, reduction, algorithm, true);
}

void exscan(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
            std::size_t count, const Reduction& reduction, Algorithm algorithm) {
  prefix(call, send, result, count, reduction, algorithm, false);
}

}  // namespace gcsim::mpi_layer
