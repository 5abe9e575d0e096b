#pragma once
// In-order delivery on one end of a link. The network may let a short message overtake a long one
// sent earlier on the same link; the link still delivers in sending order. A message arriving
// before its predecessor is held, and released the moment the predecessor arrives.
#include <cstdint>
#include <map>
#include <utility>

namespace gcsim::parix {

template <typename Message>
class InOrderDelivery {
 public:
  // Message number seq (0, 1, 2, ... in sending order) arrived; deliver(Message&&) runs for it and
  // for every held successor, in order, or not at all while a predecessor is missing.
  template <typename Deliver>
  void arrive(std::int64_t seq, Message&& m, Deliver&& deliver) {
    if (!admit(seq, m)) return;
    deliver(std::move(m));
    if (holds_any()) release_held(deliver);
  }

  // arrive() in three steps, for a caller that delivers in line without handing a callable over
  // (the runtime's delivery of every message: a closure would live on its stack): true when m is
  // next in order (the caller delivers it, then releases the held successors if any), else m is
  // held and false.
  [[gnu::always_inline]] bool admit(std::int64_t seq, Message& m) {
    if (seq != next_) [[unlikely]] {
      held_.emplace(seq, std::move(m));
      return false;
    }
    ++next_;
    return true;
  }
  bool holds_any() const { return !held_.empty(); }
  // The held successors that are now in order, each given to deliver(Message&&) in turn.
  template <typename Deliver>
  void release_held(Deliver&& deliver) {
    for (auto it = held_.find(next_); it != held_.end(); it = held_.find(next_)) {
      Message successor = std::move(it->second);
      held_.erase(it);
      ++next_;
      deliver(std::move(successor));
    }
  }

  std::int64_t delivered() const { return next_; }
  std::size_t held() const { return held_.size(); }

 private:
  std::int64_t next_ = 0;
  std::map<std::int64_t, Message> held_;  // arrived before a predecessor
};

}  // namespace gcsim::parix
