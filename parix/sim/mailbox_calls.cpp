// A simulated processor's addressed messages (parix/mailbox.hpp) over the Simulation's post office.
#include <fmt/format.h>

#include "parix/sim/simulation.hpp"

namespace gcsim::parix::detail {

namespace {

// A letter's addressee must be one of the run's processors (post and send alike).
void check_addressee(int self, int dest, int count) {
  if (dest < 0 || dest >= count) {
    throw ParixError(fmt::format("processor {}: post to processor {}, which does not exist (0..{})", self, dest, count - 1));
  }
}

}  // namespace

Request SimProcess::post(int dest, const Envelope& envelope, std::span<const std::byte> data) {
  check_addressee(id_, dest, count());
  return sim_.post_office.post(id_, dest, envelope, data, true);
}

void SimProcess::send(int dest, const Envelope& envelope, std::span<const std::byte> data) {
  check_addressee(id_, dest, count());
  sim_.post_office.post(id_, dest, envelope, data, false);
}

void SimProcess::collect(std::vector<Letter>& into) { sim_.post_office.collect(id_, into); }

void SimProcess::recycle(Bytes&& storage) { sim_.post_office.recycle(std::move(storage)); }

void SimProcess::await(std::span<const Request> requests, const WaitDescription& call, int peer) {
  auto over = [&] {
    if (sim_.post_office.has_mail(id_)) return true;
    for (const Request& r : requests) {
      if (!r.valid() || !r.state()->running()) return true;
    }
    return false;
  };
  if (over()) return;
  const machine::SimTime start = sim_.kernel.now();
  for (const Request& r : requests) r.state()->waiter = this;
  sim_.post_office.set_waiter(id_, this);
  struct Unregister {  // also when block() throws to unwind an abandoned run
    SimProcess* self;
    std::span<const Request> rs;
    ~Unregister() {
      self->blocked_description = nullptr;
      self->sim_.post_office.set_waiter(self->id_, nullptr);
      for (const Request& r : rs) r.state()->waiter = nullptr;
    }
  } unregister{this, requests};
  blocked_description = &call;
  while (!over()) block("await", peer);
  const machine::SimTime end = sim_.kernel.now();
  stats_.comm += end - start;
  // Mail that ended the wait is there since the await began (it returns at once otherwise): the
  // part before its sender posted it is waiting. A finished send is the network's doing: none.
  if (sim_.post_office.has_mail(id_)) stats_.waiting += waited_for_sender(sim_.post_office.oldest_posted(id_), start, end);
}

void SimProcess::occupy(SimTime duration, std::string_view label, bool as_comm) {
  if (duration <= 0) return;
  if (!occupy_cpu(duration, label)) throw Cancelled{};
  (as_comm ? stats_.comm : stats_.compute) += duration;
}

void SimProcess::trace_blocked(std::string_view label, SimTime start, int peer, std::int64_t bytes) {
  const machine::SimTime end = sim_.kernel.now();
  if (!sim_.trace.enabled() || end <= start) return;
  sim_.trace.record({TraceKind::wait, id_, peer, start, end, bytes, -1, label, thread_});
}

int SimProcess::node_of(int processor) const {
  if (processor < 0 || processor >= count()) {
    throw ParixError(fmt::format("processor {}: node of processor {}, which does not exist (0..{})", id_, processor, count() - 1));
  }
  return sim_.node_of[static_cast<std::size_t>(processor)];
}

}  // namespace gcsim::parix::detail
