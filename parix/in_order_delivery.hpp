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
  // for every held successor, in order, or not at all while a predecessor is missing. Always in
  // line: the runtime's delivery of every message is this call.
  template <typename Deliver>
  [[gnu::always_inline]] inline void arrive(std::int64_t seq, Message&& m, Deliver&& deliver) {
    if (seq != next_) {
      held_.emplace(seq, std::move(m));
      return;
    }
    ++next_;
    deliver(std::move(m));
    if (!held_.empty()) [[unlikely]] release_held(deliver);
  }

  std::int64_t delivered() const { return next_; }
  std::size_t held() const { return held_.size(); }

 private:
  // The held successors that are now in order. Out of line: most links never hold any, and the
  // arrival in order then needs no room for a successor on its stack.
  template <typename Deliver>
  [[gnu::noinline]] void release_held(Deliver& deliver) {
    for (auto it = held_.find(next_); it != held_.end(); it = held_.find(next_)) {
      Message successor = std::move(it->second);
      held_.erase(it);
      ++next_;
      deliver(std::move(successor));
    }
  }

  std::int64_t next_ = 0;
  std::map<std::int64_t, Message> held_;  // arrived before a predecessor
};

}  // namespace gcsim::parix
