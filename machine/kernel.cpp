#include "machine/kernel.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gcsim::machine {

void Kernel::add_chunk() {
  Action* const first = chunks_.emplace_back(std::make_unique<Action[]>(kChunk)).get();
  free_slots_.reserve(free_slots_.size() + kChunk);
  for (std::size_t i = kChunk; i-- > 0;) free_slots_.push_back(first + i);
}

// The hole at i moves towards the root while its parent is later than key, which then fills it.
inline void Kernel::sift_up(std::size_t i, const Key& key) {
  Key* h = heap_.data();
  while (i > 0) {
    const std::size_t parent = (i - 1) / kArity;
    if (!(key < h[parent])) break;
    h[i] = h[parent];
    i = parent;
  }
  h[i] = key;
}

void Kernel::at_slow(SimTime t, Action&& a) {
  if (t < now_) {
    throw std::logic_error("Kernel::at: event scheduled in the past (" + std::to_string(t) + " ps < now " +
                           std::to_string(now_) + " ps)");
  }
  Action* const slot = take_slot();
  slot->fill(std::move(a));  // free slots are empty (reset by step)
  const Key key{t, seq_++, slot};
  if (Run* const run = run_for(t)) {  // seq grows: a key not earlier than the run's end is later than all of it
    run->keys.push_back(key);  // grows a full run
    run->end = t;
    return;
  }
  heap_.push_back(key);
  sift_up(heap_.size() - 1, key);
}

Kernel::Key Kernel::pop_heap() {
  const Key top = heap_.front();
  const Key last = heap_.back();
  heap_.pop_back();
  const std::size_t n = heap_.size();
  if (n > 0) {
    // Floyd's pop on a 4-ary heap (half the levels of a binary one): the hole at the root sinks
    // along the earliest child to a leaf, then `last` climbs from there; being late, it rarely
    // climbs far. Keys are unique, so the order of pops is the same as for any heap.
    Key* h = heap_.data();
    std::size_t i = 0;
    for (std::size_t first = 1; first < n; first = kArity * i + 1) {
      std::size_t best = first;
      if (first + 3 < n) {  // all four children: a tournament of three comparisons
        const std::size_t a = first + (h[first + 1] < h[first]);
        const std::size_t b = first + 2 + (h[first + 3] < h[first + 2]);
        best = h[b] < h[a] ? b : a;
      } else {
        for (std::size_t c = first + 1; c < n; ++c) best = h[c] < h[best] ? c : best;
      }
      h[i] = h[best];
      i = best;
    }
    sift_up(i, last);
  }
  return top;
}

}  // namespace gcsim::machine
