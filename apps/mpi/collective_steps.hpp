#pragma once
// The steps the collective algorithms are made of: one tagged send or receive, a simultaneous
// exchange with one or two peers (both started before either is waited for, so the schedule does
// not depend on the runtime buffering sends), and applying a reduction on this node's CPU.
#include <algorithm>
#include <array>
#include <cstring>
#include <span>
#include <vector>

#include "apps/mpi/collective_algorithms.hpp"
#include "apps/mpi/collective_tags.hpp"

namespace gcsim::mpi_layer::steps {

using Bytes = std::vector<std::byte>;

inline void send(const CollectiveCall& call, CollectivePhase phase, int peer, std::span<const std::byte> data) {
  const CollectiveChannel::Handle h = call.channel.start_send(peer, collective_tag(call.sequence, phase), data);
  call.channel.wait_all(std::span(&h, 1));
}

inline void recv(const CollectiveCall& call, CollectivePhase phase, int peer, std::span<std::byte> into) {
  const CollectiveChannel::Handle h = call.channel.start_recv(peer, collective_tag(call.sequence, phase), into);
  call.channel.wait_all(std::span(&h, 1));
}

// Sends out to `to` and receives `in` from `from` at once.
inline void exchange(const CollectiveCall& call, CollectivePhase phase, int to, std::span<const std::byte> out,
                     int from, std::span<std::byte> in) {
  const int tag = collective_tag(call.sequence, phase);
  const std::array<CollectiveChannel::Handle, 2> h = {call.channel.start_recv(from, tag, in),
                                                      call.channel.start_send(to, tag, out)};
  call.channel.wait_all(h);
}

// inout = in op inout on count elements, charged to this node's CPU.
inline void combine(const CollectiveCall& call, const Reduction& r, const std::byte* in, std::byte* inout,
                    std::size_t count) {
  if (count == 0) return;
  call.channel.charge_reduction(count * r.element_size);
  r.combine(in, inout, count);
}

inline void copy(std::span<const std::byte> from, std::span<std::byte> to) {
  if (!from.empty() && from.data() != to.data()) std::memmove(to.data(), from.data(), from.size());
}

inline bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }
inline int largest_power_of_two_at_most(int n) {
  int p = 1;
  while (p * 2 <= n) p *= 2;
  return p;
}

// Splits total elements into parts nearly equal pieces (the first total % parts one larger):
// offsets[i]..offsets[i+1] is piece i.
inline std::vector<std::size_t> split_evenly(std::size_t total, int parts) {
  std::vector<std::size_t> offsets(static_cast<std::size_t>(parts) + 1, 0);
  const std::size_t base = total / static_cast<std::size_t>(parts), extra = total % static_cast<std::size_t>(parts);
  for (std::size_t i = 0; i < static_cast<std::size_t>(parts); ++i) offsets[i + 1] = offsets[i] + base + (i < extra);
  return offsets;
}

// The rank after which `rank` comes, counting from root, and back.
inline int relative_rank(int rank, int root, int n) { return (rank - root + n) % n; }
inline int absolute_rank(int relative, int root, int n) { return (relative + root) % n; }

}  // namespace gcsim::mpi_layer::steps
