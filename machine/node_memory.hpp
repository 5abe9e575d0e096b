#pragma once
// A node's local memory (32 MB on the GC-PowerPlus). Applications and the runtime declare what
// they hold, by kind (scene, hemicube, message buffer, ...), before the host allocates it, so that
// a run over the node's memory stops at once and can say what the node holds. Both backends keep
// one per node (the simulated one in machine::Node, the MPI one per rank).
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <boost/container/small_vector.hpp>

namespace gcsim::machine {

// What happens when a node's memory would be exceeded: the request fails (enforce), or it is
// granted and the run goes on, the peak telling how far over it went (warn).
enum class MemoryLimit { enforce, warn };
MemoryLimit parse_memory_limit(std::string_view name);  // "enforce" or "warn"

class NodeMemory {
 public:
  NodeMemory(std::int64_t capacity_bytes, MemoryLimit limit) : capacity_(capacity_bytes), limit_(limit) {}

  // Adds bytes of `kind` (negative: releases) to the memory in use. False, changing nothing, if
  // the node's memory would be exceeded under MemoryLimit::enforce; releasing always succeeds.
  bool use(std::int64_t bytes, std::string_view kind) { return use(bytes, this->kind(kind)); }
  // A handle for a kind, for callers that declare it often (the runtime, on every message):
  // use(bytes, Kind) skips the search by name. Handles number a node's kinds in first-use order.
  using Kind = std::size_t;
  Kind kind(std::string_view name);
  bool use(std::int64_t bytes, Kind kind) {
    if (bytes > 0) return add(bytes, kind);
    if (bytes < 0) release(-bytes, kind);
    return true;
  }
  // use(bytes) and use(-bytes) for bytes > 0, without the sign's test: the runtime's declarations
  // on every message (inline, twice per message).
  bool add(std::int64_t bytes, Kind kind) {
    if (limit_ == MemoryLimit::enforce && bytes > capacity_ - used_) return false;
    held_[kind] += bytes;
    used_ += bytes;
    peak_ = std::max(peak_, used_);
    return true;
  }
  // add() when the node's memory holds bytes > 0 more, under either limit (true); else changes
  // nothing and returns false, for the caller to add() and deal with the overrun. One test for
  // what add() and a test of over() afterwards ask (the runtime, on every message).
  bool add_within(std::int64_t bytes, Kind kind) {
    const std::int64_t used = used_ + bytes;
    if (used > capacity_) [[unlikely]] return false;
    held_[kind] += bytes;
    used_ = used;
    peak_ = std::max(peak_, used);
    return true;
  }
  void release(std::int64_t bytes, Kind kind) {
    std::int64_t& held = held_[kind];
    // Never below zero: a double release is the caller's slip, not memory the node gains.
    const std::int64_t change = std::min(bytes, held);
    held -= change;
    used_ -= change;
  }
  // release() of bytes the caller declared and still holds (the runtime's messages in flight,
  // each released once, on arrival): the same sums without release()'s floor at zero.
  void give_back(std::int64_t bytes, Kind kind) {
    held_[kind] -= bytes;
    used_ -= bytes;
  }
  const std::string& kind_name(Kind kind) const { return kinds_[kind]; }
  std::int64_t used() const { return used_; }
  std::int64_t peak() const { return peak_; }
  std::int64_t capacity() const { return capacity_; }
  MemoryLimit limit() const { return limit_; }
  bool over() const { return used_ > capacity_; }
  // What the node holds, largest first: "hemicube 576.0 MB, scene 1.2 MB" ("nothing" if empty).
  std::string breakdown() const;
  // "processor 3: out of node memory: hemicube 576.0 MB asked while holding scene 1.2 MB; the
  // node has 32.0 MB" ("... asked alone; ..." when it holds nothing); `asked` = 0 describes the
  // node as it is (a warning after the fact).
  std::string report(int processor, std::int64_t asked, std::string_view kind) const;

 private:
  std::int64_t capacity_;
  MemoryLimit limit_;
  std::int64_t used_ = 0;
  std::int64_t peak_ = 0;
  // By Kind (a handful per node): the names, and apart from them the bytes in use, which every
  // message declaration indexes. The first eight sums live inside the object, beside used_, so
  // a message's declaration touches one cache line of its node, not a second allocation.
  std::vector<std::string> kinds_;
  boost::container::small_vector<std::int64_t, 8> held_;
};

// "12 bytes", "1.5 KB", "32.0 MB", "10.0 GB" (binary units, as the machine file's memory_mb).
std::string format_bytes(std::int64_t bytes);

}  // namespace gcsim::machine
