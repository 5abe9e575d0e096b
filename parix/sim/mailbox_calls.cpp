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

namespace {

// occupy_send_await's state on the processor's stack: the kernel event that ends the CPU time
// records it, sends, and starts the wait where the processor would have started it right away.
struct OccupySendAwait {
  SimProcess* self;
  Simulation* sim;
  int id;
  machine::SimTime start, duration;
  std::string_view label;
  bool as_comm;
  int dest;
  const Envelope* envelope;
  std::span<const std::byte> data;
  const WaitDescription* call;
  int peer;
  Activity cpu;
  machine::SimTime awaited_from = -1;
};

}  // namespace

SimTime SimProcess::occupy_send_await(SimTime duration, std::string_view label, bool as_comm, int dest,
                                      const Envelope& envelope, std::span<const std::byte> data, const WaitDescription& call,
                                      int peer) {
  check_addressee(id_, dest, count());
  if (duration <= 0) {
    send(dest, envelope, data);
    return -1;
  }
  OccupySendAwait k{this, &sim_, id_, sim_.kernel.now(), duration, label, as_comm, dest, &envelope, data, &call, peer, {}};
  cpu_.compute(duration, [](void* p) { static_cast<OccupySendAwait*>(p)->self->end_occupy_then_send(p); }, &k);
  struct Unregister {  // also when block() throws to unwind an abandoned run
    OccupySendAwait& k;
    ~Unregister() {
      if (k.awaited_from < 0) return;
      k.self->blocked_description = nullptr;
      k.sim->post_office.set_waiter(k.id, nullptr);
    }
  } unregister{k};
  if (!wait_for_activity(k.cpu, "compute", -1)) throw Cancelled{};
  if (k.awaited_from < 0) return -1;
  while (!sim_.post_office.has_mail(id_)) block("await", peer);  // woken by anything but a letter
  const machine::SimTime end = sim_.kernel.now();
  stats_.comm += end - k.awaited_from;
  stats_.waiting += waited_for_sender(sim_.post_office.oldest_posted(id_), k.awaited_from, end);
  return k.awaited_from;
}

// In the kernel event that ends the CPU time: what occupy() and send() do after it, then await()'s
// start if no letter is there, without waking the processor (a letter will).
void SimProcess::end_occupy_then_send(void* state) {
  auto& k = *static_cast<OccupySendAwait*>(state);
  trace_compute(k.start, k.label);
  (k.as_comm ? stats_.comm : stats_.compute) += k.duration;
  sim_.post_office.post(id_, k.dest, *k.envelope, k.data, false);
  if (sim_.processes.cancelling() || sim_.post_office.has_mail(id_)) return k.cpu.complete();  // wakes it
  k.awaited_from = sim_.kernel.now();
  sim_.post_office.set_waiter(id_, this);
  blocked_description = k.call;
  blocked_call = "await";
  blocked_peer = k.peer;
  blocked_since = k.awaited_from;
  Waiter* const waiter = k.cpu.waiter;
  k.cpu.waiter = nullptr;  // done, but asleep until a letter comes
  k.cpu.complete();
  k.cpu.waiter = waiter;
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
