#pragma once
// Collective operations built from point-to-point links, as a PARIX program would write them.
// Sequential algorithms talk to the root in turn (O(N) messages in a row); tree algorithms use a
// binary tree over processor ids relative to the root (O(log N) steps). By default a connection
// is opened for every message, as in the thesis's measurements (section 4.4.2).
#include <cstring>
#include <functional>
#include <span>
#include <vector>

#include "parix/processor.hpp"

namespace gcsim::parix {

enum class BcastAlgo { sequential, tree };

struct CollectiveOptions {
  BcastAlgo algo = BcastAlgo::tree;
  bool connect_per_message = true;  // false: reuse one persistent link per peer
  int tag = 1000;                   // link tag used by this collective's connections
};

// Binary tree over ranks relative to the root: rank r has parent (r-1)/2, children 2r+1, 2r+2.
int tree_parent(int id, int root, int count);       // -1 for the root
std::vector<int> tree_children(int id, int root, int count);

// The root's data reaches every processor; every processor returns it.
Bytes broadcast(Processor& p, int root, Bytes data, const CollectiveOptions& o = {});
// Every contribution reaches the root, indexed by processor id; others get an empty vector.
std::vector<Bytes> gather(Processor& p, int root, std::span<const std::byte> mine, const CollectiveOptions& o = {});
// Every processor gets every contribution (gather to processor 0, then broadcast):
// the thesis's "all-node broadcast".
std::vector<Bytes> allgather(Processor& p, std::span<const std::byte> mine, const CollectiveOptions& o = {});
// The same exchange, without copying each part out of the packet: one allocation instead of one
// per processor (a 64-node radiosity loop made 64 x 64 of them). Moving it keeps the views valid.
struct GatheredBytes {
  Bytes packed;
  std::vector<std::span<const std::byte>> parts;  // by processor id, views into packed
  std::size_t size() const;  // the parts' bytes together
  // Whether the parts, one after the other, are `whole`: compared in place, nothing copied (a
  // processor that holds what another already concatenated need not make a copy of its own).
  bool same_as(std::span<const std::byte> whole) const;
};
GatheredBytes allgather_views(Processor& p, std::span<const std::byte> mine, const CollectiveOptions& o = {});
// Combines contributions with op (acc op= in) towards the root; the root returns the result,
// others return an empty vector. op must be associative and commutative.
using CombineOp = std::function<void(Bytes& acc, std::span<const std::byte> in)>;
Bytes reduce(Processor& p, int root, Bytes mine, const CombineOp& op, const CollectiveOptions& o = {});
Bytes allreduce(Processor& p, Bytes mine, const CombineOp& op, const CollectiveOptions& o = {});
// Returns when every processor has entered it.
void barrier(Processor& p, const CollectiveOptions& o = {});

// Typed conveniences.
template <class T>
std::vector<std::vector<T>> allgather_vectors(Processor& p, std::span<const T> mine, const CollectiveOptions& o = {}) {
  static_assert(std::is_trivially_copyable_v<T>);
  auto all = allgather(p, std::as_bytes(mine), o);
  std::vector<std::vector<T>> out(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    out[i].resize(all[i].size() / sizeof(T));
    if (!all[i].empty()) std::memcpy(out[i].data(), all[i].data(), all[i].size());
  }
  return out;
}
// The gathered elements, concatenated in processor order (a part's bytes past its last whole T
// are left out).
template <class T>
std::vector<T> concatenated(const GatheredBytes& all) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::size_t bytes = 0;
  for (const auto& part : all.parts) bytes += part.size() / sizeof(T) * sizeof(T);
  std::vector<T> out(bytes / sizeof(T));
  std::size_t at = 0;
  for (const auto& part : all.parts) {
    const std::size_t whole = part.size() / sizeof(T) * sizeof(T);
    if (whole > 0) std::memcpy(reinterpret_cast<std::byte*>(out.data()) + at, part.data(), whole);
    at += whole;
  }
  return out;
}
// Every processor's elements, concatenated in processor order.
template <class T>
std::vector<T> allgather_concatenated(Processor& p, std::span<const T> mine, const CollectiveOptions& o = {}) {
  return concatenated<T>(allgather_views(p, std::as_bytes(mine), o));
}
template <class T>
T allreduce_sum(Processor& p, T value, const CollectiveOptions& o = {}) {
  static_assert(std::is_arithmetic_v<T>);
  Bytes b(sizeof(T));
  std::memcpy(b.data(), &value, sizeof(T));
  Bytes r = allreduce(p, std::move(b), [](Bytes& acc, std::span<const std::byte> in) {
    T a, x;
    std::memcpy(&a, acc.data(), sizeof(T));
    std::memcpy(&x, in.data(), sizeof(T));
    a += x;
    std::memcpy(acc.data(), &a, sizeof(T));
  }, o);
  T out;
  std::memcpy(&out, r.data(), sizeof(T));
  return out;
}

}  // namespace gcsim::parix
