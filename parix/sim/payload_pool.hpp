#pragma once
// Message storage recycled within one simulated run, so that a message costs no heap allocation in
// steady state. post_send copies the sender's bytes into a vector taken from here; a receive that
// hands the message over by swapping with a caller-owned Bytes (Processor::recv(Link&, Bytes&),
// Request::take_into) gives the caller's old storage back, and so does a link dropping a cancelled
// message. A program that keeps using one Bytes per link thus circulates the same few vectors.
//
// Vectors are kept by capacity class (floor(log2(capacity))), so a request finds storage that
// fits without a search, and reuse is exact for a stream of equal-sized messages. Only what a run
// could soon need is kept: at most kMaxKeptBytes in all, the rest is freed at once. The pool is
// owned by the Simulation (never global), so runs in one host process share nothing.
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

#include "parix/processor.hpp"

namespace gcsim::parix::detail {

class PayloadPool {
 public:
  static constexpr std::size_t kMaxKeptBytes = std::size_t{64} << 20;

  PayloadPool() = default;
  PayloadPool(const PayloadPool&) = delete;
  PayloadPool& operator=(const PayloadPool&) = delete;

  // A vector holding a copy of data; its storage is recycled when some that fits is free.
  // Inline, as give(): both run once per message.
  Bytes copy(std::span<const std::byte> data) {
    Bytes b;
    copy_into(b, data);
    return b;
  }
  // The same into out, in place (a message's slot): no vector moved through a temporary. The
  // storage is out's own when it fits (a slot keeps a receiver's old vector), else the last vector
  // given back in its class when it fits (always, for equal-sized messages), else
  // take_elsewhere's; out's own, too small or not needed (an empty message), comes back here.
  void copy_into(Bytes& out, std::span<const std::byte> data) {
    if (data.empty()) return give(std::move(out));
    if (out.capacity() < data.size()) take_for(out, data.size());
    // Kept vectors keep their last size: a stream of equal-sized messages overwrites in place.
    if (out.size() == data.size()) return copy_bytes(out.data(), data.data(), data.size());
    out.assign(data.begin(), data.end());
  }
  // Takes back b's storage (its contents are dropped: kept as they are, to be overwritten); b is
  // left empty.
  void give(Bytes&& b) {
    const std::size_t cap = b.capacity();
    if (cap == 0) return;
    if (kept_bytes_ + cap > kMaxKeptBytes) {
      Bytes().swap(b);  // the pool is full: free it
      return;
    }
    std::vector<Bytes>& list = free_[capacity_class(cap)];
    if (list.size() == list.capacity()) return keep_growing(list, std::move(b));
    list.push_back(std::move(b));  // never reallocates here: the growth path is out of line
    kept_bytes_ += cap;
  }

  std::size_t kept() const;
  std::size_t kept_bytes() const { return kept_bytes_; }

 private:
  // memcpy, with the short payloads of most messages (up to 64 bytes) copied in line as two
  // overlapping fixed-size moves instead of a call.
  static void copy_bytes(std::byte* to, const std::byte* from, std::size_t n) {
    if (n >= 16 && n <= 64) {
      if (n >= 32) {
        std::memcpy(to, from, 32);
        std::memcpy(to + n - 32, from + n - 32, 32);
      } else {
        std::memcpy(to, from, 16);
        std::memcpy(to + n - 16, from + n - 16, 16);
      }
      return;
    }
    std::memcpy(to, from, n);
  }
  static constexpr int kClasses = 64;
  static int capacity_class(std::size_t bytes) { return std::bit_width(bytes) - 1; }  // floor(log2), bytes > 0
  Bytes take_elsewhere(std::size_t bytes);
  // Storage for `bytes` in out, whose own (too small, if any) comes back here first.
  void take_for(Bytes& out, std::size_t bytes) {
    if (out.capacity() > 0) [[unlikely]] give(std::move(out));
    std::vector<Bytes>& list = free_[capacity_class(bytes)];
    if (!list.empty() && list.back().capacity() >= bytes) {
      out.swap(list.back());
      list.pop_back();
      kept_bytes_ -= out.capacity();
    } else {
      out = take_elsewhere(bytes);
    }
  }
  [[gnu::noinline, gnu::cold]] void keep_growing(std::vector<Bytes>& list, Bytes&& b);
  Bytes pop(std::vector<Bytes>& list) {
    Bytes b = std::move(list.back());
    list.pop_back();
    kept_bytes_ -= b.capacity();
    return b;
  }
  std::array<std::vector<Bytes>, kClasses> free_;  // free_[k]: capacities in [2^k, 2^(k+1))
  std::size_t kept_bytes_ = 0;
};

}  // namespace gcsim::parix::detail
