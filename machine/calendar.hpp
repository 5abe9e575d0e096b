#pragma once
// Reservations of a resource over simulated time: sorted, non-overlapping busy intervals. A
// request takes the earliest gap of a given length at or after a given time, without moving any
// earlier reservation. The packet network keeps one per channel; connection set-up keeps one per
// connection server. Intervals that ended before a given time can be forgotten.
#include <algorithm>
#include <span>
#include <vector>

#include "machine/sim_time.hpp"

namespace gcsim::machine {

class Calendar {
 public:
  // Earliest start >= ready of a free interval [start, start + length).
  SimTime earliest(SimTime ready, SimTime length) const {
    SimTime start = ready;
    // Intervals do not overlap, so their ends are sorted too: binary search for the first one
    // that ends after we could start, then slide past every interval we would overlap.
    auto it = first_ending_after(start);
    while (it != busy_.end() && it->start < start + length) {
      start = std::max(start, it->end);
      ++it;
    }
    return start;
  }
  // Marks [start, start + length) busy; it must be free (as earliest() returned it).
  void reserve(SimTime start, SimTime length) {
    if (length <= 0) return;
    busy_.insert(first_ending_after(start), Interval{start, start + length});
  }
  SimTime take(SimTime ready, SimTime length) {
    const SimTime start = earliest(ready, length);
    reserve(start, length);
    return start;
  }
  // Drops the intervals that ended at or before t.
  void forget_before(SimTime t) { busy_.erase(busy_.begin(), first_ending_after(t)); }
  std::size_t size() const { return busy_.size(); }

  // Earliest start >= ready at which every calendar has [start, start + length) free.
  static SimTime earliest_common(std::span<Calendar* const> all, SimTime ready, SimTime length) {
    SimTime start = ready;
    for (bool moved = true; moved;) {
      moved = false;
      for (const Calendar* c : all) {
        const SimTime s = c->earliest(start, length);
        if (s != start) start = s, moved = true;
      }
    }
    return start;
  }

 private:
  struct Interval {
    SimTime start;
    SimTime end;
  };
  std::vector<Interval>::const_iterator first_ending_after(SimTime t) const {
    return std::partition_point(busy_.begin(), busy_.end(), [t](const Interval& b) { return b.end <= t; });
  }
  std::vector<Interval>::iterator first_ending_after(SimTime t) {
    return std::partition_point(busy_.begin(), busy_.end(), [t](const Interval& b) { return b.end <= t; });
  }
  std::vector<Interval> busy_;
};

}  // namespace gcsim::machine
