#pragma once
// The discrete-event kernel: a clock and a queue of actions ordered by (time, sequence number).
// Ties at equal times run in the order they were scheduled, so a run is deterministic.
#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

#include "machine/sim_time.hpp"

namespace gcsim::machine {

class Kernel {
 public:
  using Action = std::function<void()>;

  SimTime now() const { return now_; }
  std::uint64_t events_processed() const { return processed_; }
  bool idle() const { return queue_.empty(); }
  std::size_t pending() const { return queue_.size(); }

  // Schedules action at absolute time t (t >= now()).
  void at(SimTime t, Action action);
  void after(SimTime delay, Action action) { at(now_ + delay, std::move(action)); }

  // Runs the earliest pending action; returns false if there was none.
  bool step();
  // Runs until no action is pending.
  void run() {
    while (step()) {
    }
  }

 private:
  struct Event {
    SimTime time;
    std::uint64_t seq;
    Action action;
  };
  struct Later {
    bool operator()(const Event& a, const Event& b) const {
      return a.time != b.time ? a.time > b.time : a.seq > b.seq;
    }
  };
  std::priority_queue<Event, std::vector<Event>, Later> queue_;
  SimTime now_ = 0;
  std::uint64_t seq_ = 0;
  std::uint64_t processed_ = 0;
};

}  // namespace gcsim::machine
