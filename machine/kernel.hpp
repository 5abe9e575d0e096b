#pragma once
// The discrete-event kernel: a clock and a queue of actions ordered by (time, sequence number).
// Ties at equal times run in the order they were scheduled, so a run is deterministic.
// The queue holds small (time, sequence, action) keys in two parts: a run of keys scheduled in
// nondecreasing time (a FIFO: most events of a steady message flow, where each message takes the
// same time, come in order) and a 4-ary heap for the others; a step pops the earlier of the two
// fronts, so the order is the same as one heap's. The actions themselves stay in place in a pool
// of fixed-size chunks whose slots are reused, so scheduling an event allocates nothing once the
// pool has grown to the run's peak number of pending events.
#include <cstdint>
#include <memory>
#include <vector>

#include "machine/kernel_action.hpp"
#include "machine/ring_buffer.hpp"
#include "machine/sim_time.hpp"

namespace gcsim::machine {

class Kernel {
 public:
  using Action = KernelAction;

  SimTime now() const { return now_; }
  std::uint64_t events_processed() const { return processed_; }
  bool idle() const { return heap_.empty() && in_order_.empty(); }
  std::size_t pending() const { return heap_.size() + in_order_.size(); }

  // Schedules action at absolute time t (t >= now()).
  void at(SimTime t, Action&& action);  // by reference: moved once, into its slot
  void after(SimTime delay, Action&& action) { at(now_ + delay, std::move(action)); }

  // Runs the earliest pending action; returns false if there was none.
  bool step();
  // Runs until no action is pending.
  void run() {
    while (step()) {
    }
  }

 private:
  struct Key {
    SimTime time;
    std::uint64_t seq;
    KernelAction* action;  // its slot in the pool (slots never move): no index to resolve
    // One 128-bit comparison of (time, seq), without a branch; times are never negative (at()
    // refuses the past and the clock starts at 0), so they order the same as unsigned.
    bool operator<(const Key& o) const {
      using U = unsigned __int128;
      return (U(static_cast<std::uint64_t>(time)) << 64 | seq) < (U(static_cast<std::uint64_t>(o.time)) << 64 | o.seq);
    }
  };
  static constexpr std::size_t kArity = 4;  // children per heap node
  void at_slow(SimTime t, Action&& action);  // a new slot chunk, the heap, or a time in the past
  void sift_up(std::size_t i, const Key& key);
  [[gnu::noinline]] Key pop_heap();  // out of line: step() inlines into the simulation's loop
  static constexpr std::size_t kChunk = 1024;
  // Inline, as at() runs once per event; growing the pool is out of line.
  Action* take_slot() {
    if (free_slots_.empty()) add_chunk();
    Action* const slot = free_slots_.back();
    free_slots_.pop_back();
    return slot;
  }
  void add_chunk();

  RingBuffer<Key, 16> in_order_;  // keys later than or equal to their predecessor, in (time, seq) order
  // The time of the last key added to the in-order run: its back's while it holds any, else no
  // later than now_. A key at or after it extends the run (one comparison instead of the back's).
  SimTime run_end_ = 0;
  std::vector<Key> heap_;     // min-heap on (time, seq) of the keys that came out of order
  // Chunks never move, so an action runs in place even if it schedules more events.
  std::vector<std::unique_ptr<Action[]>> chunks_;
  std::vector<Action*> free_slots_;
  SimTime now_ = 0;
  std::uint64_t seq_ = 0;
  std::uint64_t processed_ = 0;
};

// at() and step() are inline: each runs once per event, called from the network models and the
// simulation's loop; the rare cases are out of line.

// The common case in line, without a call before the action's move, so that it saves few
// registers: a free slot and a key that extends the in-order run, which has room.
inline void Kernel::at(SimTime t, Action&& a) {
  if (t < run_end_ || t < now_ || free_slots_.empty() || in_order_.full()) [[unlikely]] {
    return at_slow(t, std::move(a));
  }
  Action* const slot = free_slots_.back();
  free_slots_.pop_back();
  in_order_.push_back({t, seq_++, slot});
  run_end_ = t;
  slot->fill(std::move(a));  // free slots are empty (reset by step)
}

inline bool Kernel::step() {
  Key top;
  if (!in_order_.empty() && (heap_.empty() || in_order_.front() < heap_.front())) {
    top = in_order_.front();
    in_order_.pop_front();
  } else if (!heap_.empty()) {
    top = pop_heap();
  } else {
    return false;
  }
  now_ = top.time;
  ++processed_;
  Action* const a = top.action;
  // The slot is released only after the action ran: it may schedule events, which must not reuse it.
  struct Release {
    Kernel& k;
    Action* a;
    ~Release() {
      a->reset();
      k.free_slots_.push_back(a);
    }
  } release{*this, a};
  (*a)();
  return true;
}

}  // namespace gcsim::machine
