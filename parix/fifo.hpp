#pragma once
// A first-in first-out queue that holds no memory until it is used: the queues of a link end.
// std::deque allocates about 600 bytes even when empty, and a run that opens a connection per
// message (the thesis's radiosity) keeps every link end it ever opened: 4096-node CORNELL grew by
// about 16 KB per node per loop. The slots before the front are reclaimed once they are half of
// the storage, so a queue that never empties does not grow without bound either.
#include <cstddef>
#include <utility>
#include <vector>

namespace gcsim::parix {

template <typename T>
class Fifo {
 public:
  bool empty() const { return head_ == items_.size(); }
  std::size_t size() const { return items_.size() - head_; }
  std::size_t slots() const { return items_.size(); }  // storage in use, the reclaimable slots included
  T& front() { return items_[head_]; }
  void push_back(T value) { items_.push_back(std::move(value)); }
  void pop_front() {
    if (head_ + 1 == items_.size()) {  // the last one, also the back: the queue empties
      items_.pop_back();
      if (head_ != 0) items_.clear(), head_ = 0;  // the slots before it hold nothing
      return;
    }
    items_[head_] = T{};  // releases what the slot held (a payload, a request) at once
    if (++head_ * 2 >= items_.size()) {
      items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
    }
  }
  // Removes every element for which pred is true, keeping the others in order.
  template <typename Pred>
  void erase_if(Pred pred) {
    std::size_t kept = head_;
    for (std::size_t i = head_; i < items_.size(); ++i)
      if (!pred(items_[i])) items_[kept++] = std::move(items_[i]);
    items_.resize(kept);
    if (empty()) items_.clear(), head_ = 0;
  }

 private:
  std::vector<T> items_;
  std::size_t head_ = 0;  // index of the front
};

}  // namespace gcsim::parix
