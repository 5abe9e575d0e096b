#pragma once
// The discrete-event kernel: a clock and a queue of actions ordered by (time, sequence number).
// Ties at equal times run in the order they were scheduled, so a run is deterministic.
// The queue holds small (time, sequence, action) keys in a few runs of keys scheduled in
// nondecreasing time (FIFOs: the events of a steady flow, where each takes the same delay, come in
// order; an MPI message's CPU overheads and its transfer are three such flows) and a 4-ary heap
// for the others; a step pops the earliest of the fronts, so the order is the same as one heap's,
// (time, sequence) alone deciding it. The actions themselves stay in place in a pool
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
  bool idle() const {
    for (const Run& r : runs_) {
      if (!r.keys.empty()) return false;
    }
    return heap_.empty();
  }
  std::size_t pending() const {
    std::size_t n = heap_.size();
    for (const Run& r : runs_) n += r.keys.size();
    return n;
  }

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
  // A run of keys in (time, seq) order: a key not earlier than the last one added goes at its back.
  struct Run {
    RingBuffer<Key, 16> keys;
    // The time of the last key added: its back's while it holds any, else no later than now_. A
    // key at or after it extends the run (one comparison instead of the back's).
    SimTime end = 0;
  };
  // Several runs, as a simulation's events come in a few steady flows, each with its own delay (a
  // CPU overhead, a message's transfer): the run whose end is the latest not after t, which keeps
  // each flow in a run of its own; null when every run ends after t (the key goes to the heap).
  Run* run_for(SimTime t) {
    Run* best = nullptr;
    for (Run& r : runs_) {
      if (r.end <= t && (!best || r.end > best->end)) best = &r;
    }
    return best;
  }
  void at_slow(SimTime t, Action&& action);  // a new slot chunk, a full run, the heap, or the past
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

  static constexpr std::size_t kRuns = 3;  // the MPI ring's three flows (4 runs: 1 % more instructions per message)
  Run runs_[kRuns];
  std::vector<Key> heap_;     // min-heap on (time, seq) of the keys no run could take
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
  Run* const run = run_for(t);
  if (!run || run->keys.full() || t < now_ || free_slots_.empty()) [[unlikely]] {
    return at_slow(t, std::move(a));
  }
  Action* const slot = free_slots_.back();
  free_slots_.pop_back();
  run->keys.push_back({t, seq_++, slot});
  run->end = t;
  slot->fill(std::move(a));  // free slots are empty (reset by step)
}

inline bool Kernel::step() {
  // The earliest of the runs' fronts and the heap's top: the earliest pending key.
  Run* from = nullptr;
  const Key* earliest = heap_.empty() ? nullptr : &heap_.front();
  for (Run& r : runs_) {
    if (!r.keys.empty() && (!earliest || r.keys.front() < *earliest)) earliest = &r.keys.front(), from = &r;
  }
  if (!earliest) return false;
  Key top;
  if (from) {
    top = from->keys.front();
    from->keys.drop_front();
  } else {
    top = pop_heap();
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
