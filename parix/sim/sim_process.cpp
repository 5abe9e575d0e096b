// The calls a simulated processor makes (parix/processor.hpp), as one fiber of the simulation.
#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "parix/sim/simulation.hpp"

namespace gcsim::parix::detail {

using machine::TraceKind;

// ---- SimProcess ------------------------------------------------------------------------------

SimProcess::SimProcess(Simulation& sim, int id, int thread)
    : sim_(sim), id_(id), thread_(thread), stats_(sim.stats.at(id)), node_(sim.node_of.at(id)), cpu_(sim.nodes[static_cast<std::size_t>(node_)]) {}

int SimProcess::id() const { return id_; }
int SimProcess::count() const { return sim_.processors; }
SimTime SimProcess::now() const { return sim_.kernel.now(); }

void SimProcess::block(const char* call, int peer) {
  if (sim_.processes.cancelling()) {
    if (std::uncaught_exceptions() == 0) throw Cancelled{};
    return;  // already unwinding: let the caller give up
  }
  blocked_call = call;
  blocked_peer = peer;
  blocked_since = sim_.kernel.now();
  asleep = true;
  fiber.suspend();
  blocked_call = nullptr;
  if (sim_.processes.cancelling() && std::uncaught_exceptions() == 0) throw Cancelled{};
}

bool SimProcess::wait_for_activity(Activity& a, const char* call, int peer) { return wait_in_line(a, call, peer); }

[[gnu::always_inline]] inline bool SimProcess::wait_in_line(Activity& a, const char* call, int peer) {
  while (a.running()) {
    a.waiter = this;
    block(call, peer);
    a.waiter = nullptr;
    if (sim_.processes.cancelling()) {
      a.cancel();
      return false;
    }
  }
  return true;
}

void SimProcess::compute(std::span<const OpCount> ops) { charge_ops(ops, false); }

void SimProcess::compute_in_comm(std::span<const OpCount> ops) { charge_ops(ops, true); }

void SimProcess::charge_ops(std::span<const OpCount> ops, bool as_comm) {
  machine::SimTime duration = 0;
  auto& s = stats_;
  for (const OpCount& op : ops) {
    if (op.count < 0) throw ParixError("compute: negative count for operation '" + std::string(op.op) + "'");
    try {
      duration += machine::op_time(sim_.config, op.op, op.count);
    } catch (const std::out_of_range& e) {
      throw ParixError(e.what());
    }
    auto it = s.ops.find(op.op);
    if (it == s.ops.end()) s.ops.emplace(std::string(op.op), op.count);
    else it->second += op.count;
  }
  if (duration == 0) return;
  if (!occupy_cpu(duration, ops.size() == 1 ? ops[0].op : std::string_view("compute"))) return;
  (as_comm ? s.comm : s.compute) += duration;
}

bool SimProcess::occupy_cpu(machine::SimTime duration, std::string_view label) {
  const machine::SimTime start = sim_.kernel.now();
  Activity work;
  cpu_.compute(duration, [](void* a) { static_cast<Activity*>(a)->complete(); }, &work);
  if (!wait_for_activity(work, "compute", -1)) return false;
  if (sim_.trace.enabled()) sim_.trace.record({TraceKind::compute, id_, -1, start, sim_.kernel.now(), 0, -1, label, thread_});
  return true;
}

bool SimProcess::charge_comm_cpu(machine::SimTime fixed, std::int64_t bytes, std::string_view label) {
  if (!sim_.charges_comm_cpu) return true;  // the published machine: no arithmetic, no event
  const machine::MachineConfig::CommCpu& cc = sim_.config.comm_cpu;
  const machine::SimTime d = fixed + machine::from_seconds(cc.seconds_per_byte * static_cast<double>(bytes));
  if (d == 0) return true;  // no event at all, so timings stay as they were
  const machine::SimTime start = sim_.kernel.now();
  if (!occupy_cpu(d, label)) return false;
  stats_.comm += sim_.kernel.now() - start;
  return true;
}

void SimProcess::use_memory(std::int64_t bytes, std::string_view kind) {
  if (std::string refused = sim_.memory.use(id_, bytes, kind); !refused.empty()) throw OutOfMemoryError(refused);
}

void SimProcess::close_link(std::int64_t handle) { sim_.links.close(handle); }

namespace {

// Why `link` is not processor's to use; out of line, so that the check on every send and receive
// inlines to a few instructions.
[[noreturn, gnu::noinline, gnu::cold]] void throw_bad_link(int processor, const char* call, const LinkEnd* found) {
  if (!found) throw ParixError(fmt::format("processor {}: {} on a link that is not open", processor, call));
  throw ParixError(fmt::format("processor {}: {} on a link owned by processor {}", processor, call, found->owner));
}

// The same for a request that holds nothing: wait() then needs no stack frame for the message.
[[noreturn, gnu::noinline, gnu::cold]] void throw_empty_request(int processor, const char* call) {
  throw ParixError(fmt::format("processor {}: {} on an empty request", processor, call));
}

}  // namespace

inline LinkEnd& SimProcess::end_of(const Link& link, const char* call) {
  LinkEnd* found = sim_.links.find(link.handle(), link.hint());  // null for an empty link (handle -1)
  if (!found || found->owner != id_) [[unlikely]] throw_bad_link(id_, call, found);
  return *found;
}

// The CPU hands the message to the communication processors before it travels (copying it); out
// of line, as the published machine charges nothing. False when the run was abandoned meanwhile.
bool SimProcess::charge_send_cpu(Link& link, std::size_t bytes) {
  end_of(link, "send");  // checked before the CPU is spent on it
  return charge_comm_cpu(sim_.config.comm_cpu.send, static_cast<std::int64_t>(bytes), "send_cpu");
}

Request SimProcess::abandoned_send() {
  Request abandoned = sim_.requests.take();
  abandoned.state()->complete();
  return abandoned;
}

// A send's state is over (done or withdrawn) once nothing but this process holds it: the message
// lets go when delivered, received or dropped. Only its state needs resetting; a send never sets
// the receive's fields, and a wait clears its waiter.
[[gnu::always_inline]] inline Request SimProcess::send_request() {
  if (send_request_.unique()) [[likely]] {
    send_request_.state()->rearm();
  } else {
    send_request_ = sim_.requests.take();
  }
  return send_request_;
}

// Inline into isend and send: one call per message less.
[[gnu::always_inline]] inline Request SimProcess::post_send(Link& link, std::span<const std::byte> data, bool synchronous) {
  if (sim_.charges_comm_cpu && !charge_send_cpu(link, data.size())) [[unlikely]] return abandoned_send();
  LinkEnd& e = end_of(link, "send");  // after the CPU time: links may have grown meanwhile
  Request req = send_request();
  req.state()->link = link.handle();
  req.state()->peer = e.peer;
  sim_.transport.send(e, id_, node_, sim_.node_of[e.peer], data, req, synchronous);
  auto& s = stats_;
  ++s.messages_sent;
  s.bytes_sent += static_cast<std::int64_t>(data.size());
  return req;
}

Request SimProcess::isend(Link& link, std::span<const std::byte> data) { return post_send(link, data, false); }

void SimProcess::send(Link& link, std::span<const std::byte> data) {
  Request r = post_send(link, data, true);
  wait_for(*r.state(), "send", TraceKind::send);
}

Request SimProcess::irecv(Link& link) { return post_receive(link); }

Request SimProcess::post_receive(Link& link) {
  Request req = sim_.requests.take();
  post_receive(req, link);
  return req;
}

// Inline into recv as well as irecv: a blocking receive is the common case.
[[gnu::always_inline]] inline void SimProcess::post_receive(Request& req, Link& link) {
  post_receive(req, end_of(link, "recv"), link);
}

[[gnu::always_inline]] inline void SimProcess::post_receive(Request& req, LinkEnd& e, const Link& link) {
  SimRequest& s = sim_state(req);
  s.is_receive = true;
  s.payloads = &sim_.payloads;
  s.link = link.handle();
  s.peer = e.peer;
  if (!e.arrived.empty()) {
    // Taken in its slot, not moved out: the slot keeps an empty payload and a null request.
    HeldMessage& m = e.arrived.front();
    if (!m.data.empty()) sim_.memory.release(id_, static_cast<std::int64_t>(m.data.size()), sim_.memory.received_kind());
    s.data = std::move(m.data);
    s.complete();
    if (m.synchronous) m.send.state()->complete();
    m.send = Request();
    e.arrived.drop_front();
  } else {
    PostedReceive& posted = e.receives.append();
    posted.request = req;
    posted.into = nullptr;
    posted.receiver = nullptr;
  }
}

// A receive that completed (or was withdrawn while the run was abandoned) left its link's queue,
// so only this process holds it; one still queued (the run abandoned) is left there and replaced.
[[gnu::always_inline]] inline Request& SimProcess::blocking_receive() {
  if (blocking_receive_.unique()) [[likely]] {
    SimRequest& s = sim_state(blocking_receive_);
    s.rearm();
    s.cpu_charged = false;
  } else {
    blocking_receive_ = sim_.requests.take();
  }
  return blocking_receive_;
}

void SimProcess::wait_for(RequestState& r, const char* call, TraceKind kind) {
  if (!r.running()) {  // over before the wait (a delivered isend): no time passes, nothing to trace
    if (!r.cancelled()) charge_receive_cpu(r);
    return;
  }
  wait_for_running(r, call, kind);
}

void SimProcess::wait_for_running(RequestState& r, const char* call, TraceKind kind) { wait_running(r, call, kind); }

[[gnu::always_inline]] inline void SimProcess::wait_for_receive(RequestState& r) {
  if (!r.running()) {  // the message was there already
    if (!r.cancelled()) charge_receive_cpu(r);
    return;
  }
  wait_running(r, "recv", TraceKind::recv);
}

[[gnu::always_inline]] inline void SimProcess::wait_running(RequestState& r, const char* call, TraceKind kind) {
  const machine::SimTime start = sim_.kernel.now();
  if (!wait_in_line(r, call, r.peer)) return;
  const machine::SimTime end = sim_.kernel.now();
  stats_.comm += end - start;
  if (r.cancelled()) return;  // withdrawn (before the wait, or by another thread meanwhile)
  if (r.is_receive) stats_.waiting += waited_for_sender(static_cast<SimRequest&>(r).sent_at, start, end);
  if (sim_.trace.enabled() && end > start) [[unlikely]] trace_wait(r, call, kind, start);
  charge_receive_cpu(r);
}

// Out of line: the record is built on the stack, which the waits in line need not reserve.
void SimProcess::trace_wait(const RequestState& r, const char* call, TraceKind kind, machine::SimTime start) {
  sim_.trace.record({kind, id_, r.peer, start, sim_.kernel.now(), static_cast<std::int64_t>(r.data.size()), -1, call, thread_});
}

Bytes SimProcess::recv(Link& link) {
  Request& r = blocking_receive();
  post_receive(r, link);
  wait_for_receive(*r.state());
  return r.take();
}

void SimProcess::recv(Link& link, Bytes& into) {
  LinkEnd& e = end_of(link, "recv");
  if (!sim_.charges_comm_cpu) [[likely]] {
    // The message is there already (most of a large ring's): no request, no wait, nothing to charge.
    if (!e.arrived.empty()) return sim_.transport.take_held(e, id_, into);
    if (!sim_.trace.enabled()) return receive_into(e, into);
  }
  Request& r = blocking_receive();
  post_receive(r, e, link);
  RequestState& s = *r.state();
  wait_for_receive(s);
  // Request::take_into, with the pool known: into's old storage goes back to it.
  into.swap(s.data);
  sim_.payloads.give(std::move(s.data));
}

// The wait of wait_running, with a flag for the request's state: block() throws when the run is
// abandoned, or returns while it unwinds already.
[[gnu::always_inline]] inline void SimProcess::receive_into(LinkEnd& e, Bytes& into) {
  PostedReceive& posted = e.receives.append();  // its request is null: moved on or never set
  posted.into = &into;
  posted.receiver = this;
  received_ = false;
  const int peer = e.peer;
  const machine::SimTime start = sim_.kernel.now();
  do {
    block("recv", peer);
    if (sim_.processes.cancelling()) return;
  } while (!received_);
  stats_.comm += sim_.kernel.now() - start;
  stats_.waiting += waited_for_sender(received_sent_, start, sim_.kernel.now());
}

void SimProcess::charge_receive_cpu(RequestState& r) {
  // The first test: per message. Every state this backend is given is its own (sim_state).
  if (!sim_.charges_comm_cpu || !r.is_receive || static_cast<SimRequest&>(r).cpu_charged) return;
  charge_receive_cpu_now(r);
}

// Out of line: its callers run once per message, and a published machine never charges.
[[gnu::noinline]] void SimProcess::charge_receive_cpu_now(RequestState& r) {
  static_cast<SimRequest&>(r).cpu_charged = true;
  charge_comm_cpu(sim_.config.comm_cpu.recv, static_cast<std::int64_t>(r.data.size()), "recv_cpu");
}

void SimProcess::wait(Request& r) {
  if (!r.valid()) [[unlikely]] throw_empty_request(id_, "wait");
  wait_for(*r.state(), "wait", TraceKind::wait);
}

}  // namespace gcsim::parix::detail
