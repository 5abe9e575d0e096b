#include "parix/sim/payload_pool.hpp"

#include <utility>

namespace gcsim::parix::detail {

Bytes PayloadPool::take_elsewhere(std::size_t bytes) {
  // The next two classes always fit, and hold under 8x the request, so a small message never pins
  // a large buffer.
  const int k = capacity_class(bytes);
  for (int c = k + 1; c < kClasses && c <= k + 2; ++c) {
    if (!free_[c].empty()) return pop(free_[c]);
  }
  Bytes b;
  b.reserve(bytes);
  return b;
}

// give() when its class's list is full: kept the same way, after the list grows.
void PayloadPool::keep_growing(std::vector<Bytes>& list, Bytes&& b) {
  kept_bytes_ += b.capacity();
  list.push_back(std::move(b));
}

std::size_t PayloadPool::kept() const {
  std::size_t n = 0;
  for (const std::vector<Bytes>& list : free_) n += list.size();
  return n;
}

}  // namespace gcsim::parix::detail
