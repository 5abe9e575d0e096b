// All-to-all. Pairwise exchange: in round i (1..n-1) this rank sends to rank + i and receives from
// rank - i, n(n-1) messages in n-1 rounds, one peer at a time. Linear: every message posted at
// once, the runtime's network sorts them out (MPICH's "scattered" algorithm for medium blocks).
// Bruck (Bruck et al. 1997), for small blocks: blocks rotated so position i is for rank + i; in
// round k every block whose position has bit k set moves to rank + 2^k (one message), ceil(log2 n)
// rounds, each block travelling popcount(position) hops; then rotated back.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

using Phase = CollectivePhase;

std::span<const std::byte> block_of(std::span<const std::byte> buffer, BlockLayout layout, int rank) {
  return buffer.subspan(layout.displacements[static_cast<std::size_t>(rank)], layout.counts[static_cast<std::size_t>(rank)]);
}
std::span<std::byte> block_of(std::span<std::byte> buffer, BlockLayout layout, int rank) {
  return buffer.subspan(layout.displacements[static_cast<std::size_t>(rank)], layout.counts[static_cast<std::size_t>(rank)]);
}

void pairwise(const CollectiveCall& call, std::span<const std::byte> send, BlockLayout send_layout,
              std::span<std::byte> result, BlockLayout result_layout) {
  const int n = call.channel.size(), r = call.channel.rank();
  for (int step = 1; step < n; ++step) {
    const int to = (r + step) % n, from = (r - step + n) % n;
    steps::exchange(call, Phase::Alltoallv, to, block_of(send, send_layout, to), from,
                    block_of(result, result_layout, from));
  }
}

void linear(const CollectiveCall& call, std::span<const std::byte> send, BlockLayout send_layout,
            std::span<std::byte> result, BlockLayout result_layout) {
  const int n = call.channel.size(), r = call.channel.rank(), tag = collective_tag(call.sequence, Phase::Alltoallv);
  std::vector<CollectiveChannel::Handle> handles;
  for (int step = 1; step < n; ++step)
    handles.push_back(call.channel.start_recv((r - step + n) % n, tag, block_of(result, result_layout, (r - step + n) % n)));
  for (int step = 1; step < n; ++step)
    handles.push_back(call.channel.start_send((r + step) % n, tag, block_of(send, send_layout, (r + step) % n)));
  call.channel.wait_all(handles);
}

void bruck(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, std::size_t block) {
  const int n = call.channel.size(), r = call.channel.rank();
  const auto un = static_cast<std::size_t>(n);
  steps::Bytes rotated(un * block), packed, arrived;
  for (std::size_t i = 0; i < un; ++i)  // position i: the block for rank r + i
    steps::copy(send.subspan(((static_cast<std::size_t>(r) + i) % un) * block, block),
                std::span(rotated).subspan(i * block, block));
  for (std::size_t bit = 1; bit < un; bit *= 2) {
    packed.clear();
    for (std::size_t i = bit; i < un; ++i)
      if ((i & bit) != 0) packed.insert(packed.end(), rotated.begin() + static_cast<std::ptrdiff_t>(i * block),
                                        rotated.begin() + static_cast<std::ptrdiff_t>((i + 1) * block));
    arrived.resize(packed.size());
    const int distance = static_cast<int>(bit);
    steps::exchange(call, Phase::Alltoall, (r + distance) % n, packed, (r - distance + n) % n, arrived);
    std::size_t next = 0;
    for (std::size_t i = bit; i < un; ++i)
      if ((i & bit) != 0) steps::copy(std::span(arrived).subspan(next++ * block, block), std::span(rotated).subspan(i * block, block));
  }
  for (std::size_t i = 0; i < un; ++i)  // position i now holds the block from rank r - i
    steps::copy(std::span(rotated).subspan(i * block, block),
                result.subspan(((static_cast<std::size_t>(r) + un - i) % un) * block, block));
}

}  // namespace

void alltoallv(const CollectiveCall& call, std::span<const std::byte> send, BlockLayout send_layout,
               std::span<std::byte> result, BlockLayout result_layout, Algorithm algorithm) {
  const int n = call.channel.size(), r = call.channel.rank();
  steps::copy(block_of(send, send_layout, r), block_of(result, result_layout, r));
  if (n == 1) return;
  if (resolve_algorithm(Collective::Alltoallv, algorithm, {.ranks = n}) == Algorithm::Pairwise)
    return pairwise(call, send, send_layout, result, result_layout);
  linear(call, send, send_layout, result, result_layout);
}

void alltoall(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
              std::size_t block, Algorithm algorithm) {
  const int n = call.channel.size();
  if (block == 0) return;
  const Algorithm chosen = resolve_algorithm(Collective::Alltoall, algorithm, {.bytes = block, .ranks = n});
  if (chosen == Algorithm::Bruck) return bruck(call, send, result, block);
  const std::vector<std::size_t> counts(static_cast<std::size_t>(n), block);
  std::vector<std::size_t> displacements(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < displacements.size(); ++i) displacements[i] = i * block;
  alltoallv(call, send, {counts, displacements}, result, {counts, displacements}, chosen);
}

}  // namespace gcsim::mpi_layer
