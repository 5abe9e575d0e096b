#include "parix/payload_pool.hpp"

#include <bit>
#include <utility>

namespace gcsim::parix {

void Request::take_into(Bytes& into) {
  into.swap(state_->data);
  // The caller's old storage: back to the run's pool (simulated backend), else freed now.
  if (state_->payloads) state_->payloads->give(std::move(state_->data));
  else Bytes().swap(state_->data);
}

namespace detail {

namespace {
int capacity_class(std::size_t bytes) { return std::bit_width(bytes) - 1; }  // floor(log2), bytes > 0
}  // namespace

Bytes PayloadPool::take(std::size_t bytes) {
  const int k = capacity_class(bytes);
  // Class k may hold vectors a little too small; the next two classes always fit (and are under
  // 8x the request, so a small message never pins a large buffer).
  for (int c = k; c < kClasses && c <= k + 2; ++c) {
    std::vector<Bytes>& list = free_[c];
    if (list.empty() || list.back().capacity() < bytes) continue;
    Bytes b = std::move(list.back());
    list.pop_back();
    --kept_count_;
    kept_bytes_ -= b.capacity();
    return b;
  }
  Bytes b;
  b.reserve(bytes);
  return b;
}

Bytes PayloadPool::copy(std::span<const std::byte> data) {
  if (data.empty()) return {};
  Bytes b = take(data.size());
  b.assign(data.begin(), data.end());
  return b;
}

void PayloadPool::give(Bytes&& b) {
  const std::size_t cap = b.capacity();
  if (cap == 0) return;
  if (kept_bytes_ + cap > kMaxKeptBytes) {
    Bytes().swap(b);  // the pool is full: free it
    return;
  }
  b.clear();
  free_[capacity_class(cap)].push_back(std::move(b));
  ++kept_count_;
  kept_bytes_ += cap;
}

}  // namespace detail
}  // namespace gcsim::parix
