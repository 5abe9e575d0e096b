// Opening a virtual link (Processor::connect): the two ends' calls meet in the connection matcher,
// the connection service times the set-up, and both ends wake when the link is up.
#include <fmt/format.h>

#include "parix/sim/simulation.hpp"

namespace gcsim::parix::detail {

using machine::TraceKind;

Link SimProcess::connect(int peer, int tag) {
  if (peer < 0 || peer >= count()) {
    throw ParixError(fmt::format("processor {}: connect to processor {}, which does not exist (0..{})", id_, peer, count() - 1));
  }
  if (peer == id_) throw ParixError(fmt::format("processor {}: connect to itself; a link needs two processors", id_));
  const machine::SimTime start = sim_.kernel.now();
  std::int64_t mine = -1;
  Activity set_up;  // completed by the set-up event, whichever side schedules it
  if (auto paired = sim_.connect_matching.match_or_wait(id_, peer, tag, {this, &mine, &set_up, start})) {
    const PendingConnect other = *paired;
    const auto [a, b] = ConnectionMatching::open_link(sim_.links, id_, peer);
    const machine::SimTime up = sim_.connections.set_up(node_, sim_.node_of[peer], start);
    std::int64_t* theirs = other.result;
    SimProcess* them = other.who;
    const machine::SimTime their_start = other.since;
    // Both ends' set-ups complete at once; the waiting end wakes first.
    // b by an init-capture: capturing a structured binding by name needs clang 16.
    sim_.kernel.at(up, [theirs, their_set_up = other.set_up, &set_up, their_end = b] {
      *theirs = their_end;
      their_set_up->complete();
      set_up.complete();
    });
    if (!wait_for_activity(set_up, "connect", peer)) return {};
    mine = a;
    sim_.stats[peer].connections += 1;
    sim_.stats[peer].waiting += start - their_start;  // the partner waited for this end to ask
    stats_.connections += 1;
    if (sim_.trace.enabled()) {
      sim_.trace.record({TraceKind::connect, peer, id_, their_start, up, 0, -1, "connect", them->thread()});
      sim_.trace.record({TraceKind::connect, id_, peer, start, up, 0, -1, "connect", thread_});
    }
  } else if (!wait_for_activity(set_up, "connect", peer)) {
    return {};
  }
  if (!charge_comm_cpu(sim_.config.comm_cpu.connect, 0, "connect_cpu")) return {};
  const machine::SimTime took = sim_.kernel.now() - start;
  stats_.comm += took;
  stats_.connect += took;
  return Link(this, peer, tag, mine, sim_.links.hint_of(mine));
}

}  // namespace gcsim::parix::detail
