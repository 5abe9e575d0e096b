#pragma once
// A first-in first-out queue that holds no memory until it is used: the queues of a link end.
// std::deque allocates about 600 bytes even when empty, and a run that opens a connection per
// message (the thesis's radiosity) keeps every link end it ever opened: 4096-node CORNELL grew by
// about 16 KB per node per loop. One circular array whose capacity is a power of two, doubled
// when full, so a queue that never empties neither grows nor moves its elements to compact, and
// taking the front costs an index step (a vector with a moving head reset the slot and erased
// the dead ones: 98 host instructions per message when messages wait for their receive).
#include <cstddef>
#include <utility>
#include <vector>

namespace gcsim::parix {

template <typename T>
class Fifo {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  std::size_t slots() const { return items_.size(); }  // storage held: 0 until first used, then its peak
  T& front() { return items_[head_]; }
  void push_back(T&& value) {
    if (size_ == capacity_) [[unlikely]] grow();
    items_[(head_ + size_) & mask_] = std::move(value);
    ++size_;
  }
  void push_back(const T& value) {
    if (size_ == capacity_) [[unlikely]] grow();
    items_[(head_ + size_) & mask_] = value;
    ++size_;
  }
  // A new back slot, holding a moved-from value or a default one, for the caller to fill in place
  // (no temporary to move in).
  T& append() {
    if (size_ == capacity_) [[unlikely]] grow();
    return items_[(head_ + size_++) & mask_];
  }
  // Removes the front, whose contents the caller has moved out (or released): its slot keeps the
  // moved-from value until a push_back overwrites it.
  void drop_front() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }
  void pop_front() {
    items_[head_] = T{};  // releases what the slot held (a payload, a request) at once
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
  // Out of line: a queue grows to its peak a few times, then never again.
  [[gnu::noinline]] void grow() {
    std::vector<T> bigger(items_.empty() ? 2 : items_.size() * 2);
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = std::move(items_[(head_ + i) & mask_]);
    items_.swap(bigger);
    head_ = 0;
    capacity_ = items_.size();
    mask_ = capacity_ - 1;
  }
  std::vector<T> items_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;  // items_.size(), kept: the vector's size divides by sizeof(T)
  std::size_t mask_ = 0;
};

}  // namespace gcsim::parix
