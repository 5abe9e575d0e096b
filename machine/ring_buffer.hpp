#pragma once
// A first-in first-out queue in one circular array whose capacity is a power of two (an index is
// a mask), doubled when full. A queue that never empties neither grows nor moves its elements to
// compact, taking the front is an index step, and until first used it holds no memory (std::deque
// allocates about 600 bytes even when empty). The kernel keeps its in-order events in one; parix
// a link end's queues, which a run that opens a connection per message keeps for every link end
// it ever opened (4096-node CORNELL grew by about 16 KB per node per loop with deques).
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace gcsim::machine {

// FirstCapacity: the slots taken on first use, a power of two.
template <typename T, std::size_t FirstCapacity = 2>
class RingBuffer {
  static_assert(FirstCapacity > 0 && (FirstCapacity & (FirstCapacity - 1)) == 0);

 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }  // storage held: 0 until first used, then its peak
  bool full() const { return size_ == capacity_; }    // one comparison: the kernel asks on every event
  T& front() { return items_[head_]; }
  const T& front() const { return items_[head_]; }
  const T& back() const { return items_[(head_ + size_ - 1) & mask_]; }
  void push_back(T&& value) {
    if (full()) [[unlikely]] grow();
    items_[(head_ + size_) & mask_] = std::move(value);
    ++size_;
  }
  void push_back(const T& value) {
    if (full()) [[unlikely]] grow();
    items_[(head_ + size_) & mask_] = value;
    ++size_;
  }
  // A new back slot, holding a moved-from value or a default one, for the caller to fill in place
  // (no temporary to move in).
  T& append() {
    if (full()) [[unlikely]] grow();
    return items_[(head_ + size_++) & mask_];
  }
  void pop_back() { --size_; }
  // Removes the front, whose contents the caller has moved out (or released): its slot keeps the
  // moved-from value until a push_back overwrites it.
  void drop_front() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }
  // Removes the front and releases at once what its slot held (a payload, a request).
  void pop_front() {
    if constexpr (!std::is_trivially_destructible_v<T>) items_[head_] = T{};
    drop_front();
  }
  // Removes every element for which pred is true, keeping the others in order.
  template <typename Pred>
  void erase_if(Pred pred) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      T& item = items_[(head_ + i) & mask_];
      if (!pred(item)) items_[(head_ + kept++) & mask_] = std::move(item);
    }
    for (std::size_t i = kept; i < size_; ++i) items_[(head_ + i) & mask_] = T{};
    size_ = kept;
  }

 private:
  // Out of line: a queue grows to its peak a few times per run, then never again.
  [[gnu::noinline]] void grow() {
    std::vector<T> bigger(items_.empty() ? FirstCapacity : items_.size() * 2);
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = std::move(items_[(head_ + i) & mask_]);
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
