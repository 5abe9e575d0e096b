#pragma once
// A first-in first-out queue of trivially copyable values in one circular array whose capacity is
// a power of two (an index is a mask), doubled when full. Unlike a vector with a moving head it
// needs no compaction when it never empties; the kernel keeps its in-order events in one.
#include <cstddef>
#include <type_traits>
#include <vector>

namespace gcsim::machine {

template <typename T>
class RingBuffer {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool full() const { return size_ == capacity_; }  // one comparison: the kernel asks on every event
  const T& front() const { return items_[head_]; }
  const T& back() const { return items_[(head_ + size_ - 1) & mask_]; }
  void push_back(const T& v) {
    if (full()) grow();
    items_[(head_ + size_) & mask_] = v;
    ++size_;
  }
  void pop_back() { --size_; }
  void pop_front() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }

 private:
  // Out of line: the queue grows to its peak a few times per run, then never again.
  [[gnu::noinline]] void grow() {
    std::vector<T> bigger(items_.empty() ? 16 : items_.size() * 2);
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = items_[(head_ + i) & mask_];
    items_.swap(bigger);
    head_ = 0;
    capacity_ = items_.size();
    mask_ = capacity_ - 1;
  }
  std::vector<T> items_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;  // items_.size(), kept apart: the vector's size divides by sizeof(T)
  std::size_t mask_ = 0;
};

}  // namespace gcsim::machine
