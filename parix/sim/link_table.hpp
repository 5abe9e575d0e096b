#pragma once
// The link ends of one simulation. A program that opens a connection per message, as the thesis's
// radiosity does, opens millions of links in a long run; each pair's slots are reused once both
// ends are closed and nothing is left on either (End::idle), so the table holds about as many ends
// as are open at once instead of every end ever opened (4096-node CORNELL kept about 2.5 KB per
// node per loop before).
//
// A handle names a slot and the generation of its use: (generation << 32) | slot. A handle whose
// slot has been reused since is recognised as stale, never taken for the new link.
#include <cstdint>
#include <utility>
#include <vector>

#include "parix/sim/stable_vector.hpp"

namespace gcsim::parix {

// End: default-constructible, with `bool open`, `std::int64_t peer_end` (a handle) and
// `bool idle(const End& peer) const` (nothing in flight, held, arrived or waiting on this end).
template <typename End>
class LinkTable {
 public:
  // A new pair of ends, each the other's peer; returns their handles.
  std::pair<std::int64_t, std::int64_t> open_pair() {
    const std::int64_t a = take_slot(), b = take_slot();
    at(a).peer_end = b;
    at(b).peer_end = a;
    return {a, b};
  }

  // The end of a live handle; nullptr for a handle that never was or whose slot was reused.
  End* find(std::int64_t handle) {
    const std::uint64_t slot = slot_of(handle);
    if (handle < 0 || slot >= slots_.size() || slots_[slot].generation != generation_of(handle)) return nullptr;
    return &slots_[slot].end;
  }
  // The same through the hint of that handle (hint_of(handle), kept with it: slots never move),
  // which saves finding the slot; the generation check is find's.
  End* find(std::int64_t handle, const void* hint) {
    if (hint) [[likely]] {
      const Slot& s = *static_cast<const Slot*>(hint);
      if (s.generation == generation_of(handle)) return const_cast<End*>(&s.end);
    }
    return find(handle);
  }
  const void* hint_of(std::int64_t handle) { return &slots_[slot_of(handle)]; }
  // The end of a handle known to be live (a message's destination keeps its pair from reuse).
  End& at(std::int64_t handle) { return slots_[slot_of(handle)].end; }

  // Closes the end of `handle` (a stale handle is ignored) and frees its pair if done.
  void close(std::int64_t handle) {
    if (End* e = find(handle)) {
      e->open = false;
      release_if_done(handle);
    }
  }

  // Frees the pair of `handle` once both ends are closed and idle. Never call it while the end is
  // in use further up the stack (during a delivery on it).
  void release_if_done(std::int64_t handle) {
    End* e = find(handle);
    if (!e || e->open) return;
    End& peer = at(e->peer_end);
    if (peer.open || !e->idle(peer) || !peer.idle(*e)) return;
    free_slot(e->peer_end);
    free_slot(handle);
  }

  std::size_t slots() const { return slots_.size(); }            // storage held: the most ends open at once
  std::size_t open_ends() const { return slots_.size() - free_.size(); }

 private:
  struct Slot {
    End end;
    std::uint32_t generation = 0;
  };
  static std::uint64_t slot_of(std::int64_t handle) { return static_cast<std::uint64_t>(handle) & 0xffffffffu; }
  static std::uint32_t generation_of(std::int64_t handle) { return static_cast<std::uint32_t>(static_cast<std::uint64_t>(handle) >> 32); }
  static std::int64_t handle_of(std::uint64_t slot, std::uint32_t generation) {
    return static_cast<std::int64_t>((std::uint64_t(generation & 0x7fffffffu) << 32) | slot);
  }

  std::int64_t take_slot() {
    if (free_.empty()) {
      slots_.emplace_back();
      return handle_of(slots_.size() - 1, 0);
    }
    const std::uint64_t slot = free_.back();
    free_.pop_back();
    return handle_of(slot, slots_[slot].generation);
  }
  void free_slot(std::int64_t handle) {
    Slot& s = slots_[slot_of(handle)];
    s.end = End{};
    s.generation = (s.generation + 1) & 0x7fffffffu;  // handles stay non-negative
    free_.push_back(slot_of(handle));
  }

  StableVector<Slot> slots_;  // ends keep their address while the table grows
  std::vector<std::uint64_t> free_;
};

}  // namespace gcsim::parix
