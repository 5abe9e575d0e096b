#pragma once
// Pairs connect calls: processor a's connect(b, tag) meets processor b's connect(a, tag). Calls
// that find no partner wait in call order, so the k-th connect from a to b with a tag pairs with
// the k-th from b to a with the same tag (PARIX's virtual links are FIFO per pair and tag).
// Tags keep links apart: a connect never pairs with one of another tag.
#include <deque>
#include <map>
#include <optional>
#include <tuple>

namespace gcsim::parix {

template <typename Waiting>
class ConnectionMatcher {
 public:
  // A connect from `from` to `to`: returns the oldest waiting call from `to` to `from` with this
  // tag (now paired, no longer waiting), or records `me` as waiting and returns nothing.
  std::optional<Waiting> match_or_wait(int from, int to, int tag, Waiting me) {
    auto theirs = pending_.find({to, from, tag});
    if (theirs != pending_.end() && !theirs->second.empty()) {
      Waiting other = std::move(theirs->second.front());
      theirs->second.pop_front();
      if (theirs->second.empty()) pending_.erase(theirs);
      return other;
    }
    pending_[{from, to, tag}].push_back(std::move(me));
    return std::nullopt;
  }

  // Connect calls still waiting for their partner.
  std::size_t waiting() const {
    std::size_t n = 0;
    for (const auto& [key, calls] : pending_) n += calls.size();
    return n;
  }

 private:
  std::map<std::tuple<int, int, int>, std::deque<Waiting>> pending_;  // (from, to, tag) -> calls in order
};

}  // namespace gcsim::parix
