// The calls of a simulated processor that wait for one of several requests, withdraw one or start a
// thread (parix/processor.hpp); the per-message calls are in sim_process.cpp.
#include <algorithm>

#include <fmt/format.h>

#include "parix/sim/sim_request.hpp"
#include "parix/sim/simulation.hpp"

namespace gcsim::parix::detail {

using machine::TraceKind;

namespace {

// The lowest index of a completed request; rs.size() if none is, while some still run.
std::size_t first_done(std::span<Request* const> rs, int processor) {
  bool any_running = false;
  for (std::size_t i = 0; i < rs.size(); ++i) {
    if (!rs[i]->valid()) throw ParixError(fmt::format("processor {}: wait_any on an empty request", processor));
    if (rs[i]->test()) return i;
    any_running = any_running || rs[i]->state()->running();
  }
  if (!any_running) throw ParixError(fmt::format("processor {}: wait_any on {} requests, all cancelled", processor, rs.size()));
  return rs.size();
}

}  // namespace

std::size_t SimProcess::wait_any(std::span<Request* const> rs) {
  if (rs.empty()) throw ParixError(fmt::format("processor {}: wait_any on no requests", id_));
  const machine::SimTime start = sim_.kernel.now();
  std::size_t i;
  while ((i = first_done(rs, id_)) == rs.size()) {
    for (Request* r : rs) r->state()->waiter = this;
    block("wait_any", rs.size() == 1 ? rs[0]->state()->peer : -1);
    for (Request* r : rs) r->state()->waiter = nullptr;
    if (sim_.processes.cancelling()) return 0;
  }
  const machine::SimTime end = sim_.kernel.now();
  stats_.comm += end - start;
  if (rs[i]->state()->is_receive) stats_.waiting += waited_for_sender(sim_state(*rs[i]).sent_at, start, end);
  if (sim_.trace.enabled() && end > start) {
    sim_.trace.record({TraceKind::wait, id_, rs[i]->state()->peer, start, end, 0, -1, "wait_any", thread_});
  }
  charge_receive_cpu(*rs[i]->state());
  return i;
}

bool SimProcess::cancel(Request& r) {
  if (!r.valid()) throw ParixError(fmt::format("processor {}: cancel on an empty request", id_));
  RequestState& s = *r.state();
  if (!s.running()) return s.cancelled();
  if (s.is_receive) {
    // Not yet matched, so still queued on its link: the link's next message goes to the next one.
    // Its link is still there: a queued receive keeps the link's slots from reuse.
    LinkEnd& e = sim_.links.at(s.link);
    if (e.owner != id_) throw ParixError(fmt::format("processor {}: cancel of a receive of processor {}", id_, e.owner));
    e.receives.erase_if([&s](const PostedReceive& q) { return q.request.state() == &s; });
    sim_.links.release_if_done(s.link);
  }
  // A send: its message is still in the network (or held for in-order delivery); accept drops it.
  s.cancel();
  return true;
}

Thread SimProcess::spawn(std::function<void(Processor&)> body) {
  SimProcess* t = &sim_.processes.add(std::make_unique<SimProcess>(sim_, id_, sim_.processes.threads_of(id_)));
  sim_.processes.launch(t, std::move(body));
  return Thread([this, t] {
    while (!t->finished) {
      t->joiner = this;
      block("join", id_);
      if (sim_.processes.cancelling()) return;
    }
  });
}

}  // namespace gcsim::parix::detail
