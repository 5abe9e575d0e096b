#pragma once
// Routes by (source, destination) pair, with the per-channel accounting of the messages that took
// them deferred. A message of the analytic model needs its route only to add its bytes and busy
// time to every channel it crosses; routing and that loop cost more than the rest of the model.
// Here a pair's hop count and route are looked up once, its messages only add to the pair's two
// sums, and the sums reach the channels when the entry is evicted or flush() is called. Sums of
// integers do not depend on their order, so the channels' totals are exactly the eager ones.
//
// Direct-mapped: a pair lives in the one entry its hash names, so a lookup is a multiplication and
// a comparison; a pair colliding with another evicts it (flushing its sums first).
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "machine/interconnect.hpp"
#include "machine/sim_time.hpp"

namespace gcsim::machine {

class RouteCache {
 public:
  struct alignas(64) Entry {  // one cache line; indexing is a shift
    int src = -1;  // -1: empty
    int dst = -1;
    int hops = 0;
    SimTime latency = 0;  // the user's (the analytic model's) latency for hops, kept with them
    std::int64_t bytes = 0;  // not yet added to the route's channels
    SimTime busy = 0;
    std::vector<int> route;
  };

  // Enough entries for every pair of `nodes` nodes, up to max_entries (a power of two).
  explicit RouteCache(const Interconnect& routing, std::size_t max_entries = 4096) : routing_(routing) {
    const auto n = static_cast<std::size_t>(routing.nodes());
    std::size_t want = n > 0 && n * n < max_entries ? n * n : max_entries;
    entries_.resize(std::bit_ceil(std::max<std::size_t>(want, 2)));  // 2+: the hash's shift stays below 64
    shift_ = 64 - std::countr_zero(entries_.size());
  }

  // The entry of src -> dst, routed on first use (or after an eviction, which flushes the
  // evicted pair's sums into bytes_out / busy_out first).
  Entry& find(int src, int dst, std::vector<std::int64_t>& bytes_out, std::vector<SimTime>& busy_out) {
    Entry& e = entries_[index(src, dst)];
    if (e.src != src || e.dst != dst) [[unlikely]] fill(e, src, dst, bytes_out, busy_out);
    return e;
  }
  // The entry of src -> dst if it holds that pair, else null (nothing changes).
  Entry* lookup(int src, int dst) {
    Entry& e = entries_[index(src, dst)];
    return e.src == src && e.dst == dst ? &e : nullptr;
  }
  // Adds every entry's pending sums to the channels.
  void flush(std::vector<std::int64_t>& bytes_out, std::vector<SimTime>& busy_out) {
    for (Entry& e : entries_) flush(e, bytes_out, busy_out);
  }
  std::size_t entries() const { return entries_.size(); }

 private:
  std::size_t index(int src, int dst) const {
    const std::uint64_t key = std::uint64_t(std::uint32_t(src)) << 32 | std::uint32_t(dst);
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  static void flush(Entry& e, std::vector<std::int64_t>& bytes_out, std::vector<SimTime>& busy_out) {
    if (e.bytes == 0 && e.busy == 0) return;
    for (int ch : e.route) {
      bytes_out[ch] += e.bytes;
      busy_out[ch] += e.busy;
    }
    e.bytes = 0;
    e.busy = 0;
  }
  [[gnu::noinline]] void fill(Entry& e, int src, int dst, std::vector<std::int64_t>& bytes_out,
                              std::vector<SimTime>& busy_out) {
    flush(e, bytes_out, busy_out);
    e.src = src;
    e.dst = dst;
    e.hops = routing_.hops(src, dst);
    routing_.route(src, dst, e.route);
  }

  const Interconnect& routing_;
  std::vector<Entry> entries_;
  int shift_ = 63;  // 64 - log2(entries)
};

}  // namespace gcsim::machine
