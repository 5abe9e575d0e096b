// Gather and scatter. Binomial (n-1 messages, ceil(log2 n) rounds): relative rank rel collects the
// blocks of relative ranks [rel, rel + lowest bit of rel) in a scratch buffer in relative order
// and hands them to its parent in one message; scatter runs the same tree downwards. Linear: the
// root receives (sends) one message per other rank, all posted at once. The v forms are linear
// only, as in MPICH: only the root knows every count, so no rank could size a subtree's message.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

using Phase = CollectivePhase;

int lowest_bit_or(int rel, int n) {
  int mask = 1;
  while (mask < n && (rel & mask) == 0) mask *= 2;
  return mask;
}

// The root's blocks in relative order (relative block i is rank root + i's) and back.
void rotate_to_ranks(std::span<const std::byte> relative, std::span<std::byte> ranks, std::size_t block, int root) {
  const std::size_t n = relative.size() / block, first = n - static_cast<std::size_t>(root);
  steps::copy(relative.first(first * block), ranks.subspan(static_cast<std::size_t>(root) * block));
  steps::copy(relative.subspan(first * block), ranks.first(static_cast<std::size_t>(root) * block));
}

void rotate_from_ranks(std::span<const std::byte> ranks, std::span<std::byte> relative, std::size_t block, int root) {
  const std::size_t n = ranks.size() / block, first = n - static_cast<std::size_t>(root);
  steps::copy(ranks.subspan(static_cast<std::size_t>(root) * block), relative.first(first * block));
  steps::copy(ranks.first(static_cast<std::size_t>(root) * block), relative.subspan(first * block));
}

void binomial_gather(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                     int root) {
  const int n = call.channel.size(), rel = steps::relative_rank(call.channel.rank(), root, n);
  const std::size_t block = send.size();
  const int subtree = std::min(lowest_bit_or(rel, n), n - rel);
  steps::Bytes held(static_cast<std::size_t>(subtree) * block);
  steps::copy(send, std::span(held).first(block));
  for (int mask = 1; mask < n; mask *= 2) {
    if ((rel & mask) != 0) {
      steps::send(call, Phase::Gather, steps::absolute_rank(rel - mask, root, n), held);
      return;
    }
    if (rel + mask >= n) continue;
    const std::size_t blocks = static_cast<std::size_t>(std::min(mask, n - rel - mask));
    steps::recv(call, Phase::Gather, steps::absolute_rank(rel + mask, root, n),
                std::span(held).subspan(static_cast<std::size_t>(mask) * block, blocks * block));
  }
  rotate_to_ranks(held, result, block, root);
}

void binomial_scatter(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                      int root) {
  const int n = call.channel.size(), rel = steps::relative_rank(call.channel.rank(), root, n);
  const std::size_t block = result.size();
  const int mask = lowest_bit_or(rel, n), subtree = std::min(mask, n - rel);
  steps::Bytes held(static_cast<std::size_t>(subtree) * block);
  if (rel == 0) rotate_from_ranks(send, held, block, root);
  else steps::recv(call, Phase::Scatter, steps::absolute_rank(rel - mask, root, n), held);
  for (int child = mask / 2; child > 0; child /= 2) {
    if (rel + child >= n) continue;
    const std::size_t blocks = static_cast<std::size_t>(std::min(child, n - rel - child));
    steps::send(call, Phase::Scatter, steps::absolute_rank(rel + child, root, n),
                std::span<const std::byte>(held).subspan(static_cast<std::size_t>(child) * block, blocks * block));
  }
  steps::copy(std::span<const std::byte>(held).first(block), result);
}

// The root's side of a linear gatherv or scatterv: one message per other rank, posted at once.
template <class Start>
void post_all_at_root(const CollectiveCall& call, Start start) {
  std::vector<CollectiveChannel::Handle> handles;
  for (int peer = 0; peer < call.channel.size(); ++peer)
    if (peer != call.channel.rank()) start(peer, handles);
  call.channel.wait_all(handles);
}

}  // namespace

void gather(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, int root,
            Algorithm algorithm) {
  const int n = call.channel.size();
  if (send.empty()) return;
  if (resolve_algorithm(Collective::Gather, algorithm, {.bytes = send.size(), .ranks = n}) == Algorithm::Binomial)
    return binomial_gather(call, send, result, root);
  const std::vector<std::size_t> counts(static_cast<std::size_t>(n), send.size());
  std::vector<std::size_t> displacements(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < displacements.size(); ++i) displacements[i] = i * send.size();
  gatherv(call, send, result, counts, displacements, root);
}

void gatherv(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
             std::span<const std::size_t> counts, std::span<const std::size_t> displacements, int root,
             Algorithm algorithm) {
  const int r = call.channel.rank();
  resolve_algorithm(Collective::Gatherv, algorithm, {.ranks = call.channel.size()});  // only checks the name
  if (r != root) {
    if (!send.empty()) steps::send(call, Phase::Gatherv, root, send);
    return;
  }
  const auto at = [&](int peer) {
    return result.subspan(displacements[static_cast<std::size_t>(peer)], counts[static_cast<std::size_t>(peer)]);
  };
  steps::copy(send, at(r));
  const int tag = collective_tag(call.sequence, Phase::Gatherv);
  post_all_at_root(call, [&](int peer, std::vector<CollectiveChannel::Handle>& handles) {
    if (!at(peer).empty()) handles.push_back(call.channel.start_recv(peer, tag, at(peer)));
  });
}

void scatter(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, int root,
             Algorithm algorithm) {
  const int n = call.channel.size();
  if (result.empty()) return;
  if (resolve_algorithm(Collective::Scatter, algorithm, {.bytes = result.size(), .ranks = n}) == Algorithm::Binomial)
    return binomial_scatter(call, send, result, root);
  const std::vector<std::size_t> counts(static_cast<std::size_t>(n), result.size());
  std::vector<std::size_t> displacements(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < displacements.size(); ++i) displacements[i] = i * result.size();
  scatterv(call, send, counts, displacements, result, root);
}

void scatterv(const CollectiveCall& call, std::span<const std::byte> send, std::span<const std::size_t> counts,
              std::span<const std::size_t> displacements, std::span<std::byte> result, int root,
              Algorithm algorithm) {
  const int r = call.channel.rank();
  resolve_algorithm(Collective::Scatterv, algorithm, {.ranks = call.channel.size()});  // only checks the name
  if (r != root) {
    if (!result.empty()) steps::recv(call, Phase::Scatterv, root, result);
    return;
  }
  const auto at = [&](int peer) {
    return send.subspan(displacements[static_cast<std::size_t>(peer)], counts[static_cast<std::size_t>(peer)]);
  };
  steps::copy(at(r), result);
  const int tag = collective_tag(call.sequence, Phase::Scatterv);
  post_all_at_root(call, [&](int peer, std::vector<CollectiveChannel::Handle>& handles) {
    if (!at(peer).empty()) handles.push_back(call.channel.start_send(peer, tag, at(peer)));
  });
}

}  // namespace gcsim::mpi_layer
