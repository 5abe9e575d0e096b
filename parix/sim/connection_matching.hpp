#pragma once
// Connection matching of the simulated runtime: a connect call waits here for its other end
// (ConnectionMatcher pairs the calls FIFO per pair and tag), and two calls that meet open a pair
// of link ends, each knowing the other.
#include <cstdint>
#include <optional>
#include <utility>

#include "machine/sim_time.hpp"
#include "parix/activity.hpp"
#include "parix/sim/connection_matcher.hpp"
#include "parix/sim/link_end.hpp"
#include "parix/sim/link_table.hpp"

namespace gcsim::parix::detail {

class SimProcess;

// A connect call waiting for its other end.
struct PendingConnect {
  SimProcess* who;
  std::int64_t* result;  // the link end it gets
  Activity* set_up;      // completed when the link is up
  machine::SimTime since;
};

class ConnectionMatching {
 public:
  // A connect from `from` to `to`: the oldest call from `to` to `from` with this tag, now paired,
  // or nothing, and `me` waits.
  std::optional<PendingConnect> match_or_wait(int from, int to, int tag, const PendingConnect& me) {
    return calls_.match_or_wait(from, to, tag, me);
  }
  std::size_t waiting() const { return calls_.waiting(); }

  // The two ends of a new link between processors a and b: (a's end, b's end).
  static std::pair<std::int64_t, std::int64_t> open_link(LinkTable<LinkEnd>& links, int a, int b) {
    const auto [end_a, end_b] = links.open_pair();
    LinkEnd& ea = links.at(end_a);
    LinkEnd& eb = links.at(end_b);
    ea.owner = a, ea.peer = b, ea.peer_at = &eb;
    eb.owner = b, eb.peer = a, eb.peer_at = &ea;
    return {end_a, end_b};
  }

 private:
  ConnectionMatcher<PendingConnect> calls_;
};

}  // namespace gcsim::parix::detail
