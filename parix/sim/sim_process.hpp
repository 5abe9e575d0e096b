#pragma once
// A process of the simulated runtime: one processor's main thread or a thread it spawned, running
// in its own fiber. It implements the PARIX calls (sim_process.cpp; connect in link_setup.cpp;
// wait_any, cancel and spawn in process_control.cpp) over the Simulation's parts.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>

#include "machine/sim_time.hpp"
#include "machine/trace.hpp"
#include "parix/mailbox.hpp"
#include "parix/processor.hpp"
#include "parix/run_result.hpp"
#include "parix/activity.hpp"
#include "parix/sim/fiber_processes.hpp"
#include "parix/sim/link_end.hpp"

namespace gcsim::machine {
class Node;
}

namespace gcsim::parix::detail {

// Of a receive or wait blocked from start to end, the part before the sender of the message that
// ended it had sent it: "waiting" (docs/run-records.md); the rest is communicating.
inline machine::SimTime waited_for_sender(machine::SimTime sent, machine::SimTime start, machine::SimTime end) {
  return std::clamp(sent, start, end) - start;
}

using machine::TraceKind;

class Simulation;

class SimProcess final : public Processor, public Mailbox, public Waiter {
 public:
  SimProcess(Simulation& sim, int id, int thread);
  ~SimProcess() override { drop_persistent_links(); }

  int id() const override;
  int count() const override;
  SimTime now() const override;
  void compute(std::span<const OpCount> ops) override;
  void compute_in_comm(std::span<const OpCount> ops) override;
  void use_memory(std::int64_t bytes, std::string_view kind) override;
  Link connect(int peer, int tag) override;
  void send(Link& link, std::span<const std::byte> data) override;
  Bytes recv(Link& link) override;
  void recv(Link& link, Bytes& into) override;
  Request isend(Link& link, std::span<const std::byte> data) override;
  Request irecv(Link& link) override;
  void wait(Request& r) override;
  std::size_t wait_any(std::span<Request* const> rs) override;
  bool cancel(Request& r) override;
  Thread spawn(std::function<void(Processor&)> body) override;
  // Addressed messages (parix/mailbox.hpp), in mailbox_calls.cpp.
  Request post(int dest, const Envelope& envelope, std::span<const std::byte> data) override;
  void send(int dest, const Envelope& envelope, std::span<const std::byte> data) override;
  void collect(std::vector<Letter>& into) override;
  void recycle(Bytes&& storage) override;
  void await(std::span<const Request> requests, const WaitDescription& call, int peer) override;
  using Mailbox::await;
  void occupy(SimTime duration, std::string_view label, bool as_comm) override;
  void trace_blocked(std::string_view label, SimTime start, int peer, std::int64_t bytes) override;
  int node_of(int processor) const override;

  // Suspends this fiber until wake(); `call` and `peer` describe the wait for deadlock reports.
  void block(const char* call, int peer);
  void wake() override {  // in line: MessageTransport::hand_over wakes a receiver once per message
    if (!asleep) return;
    asleep = false;
    fiber.resume();
  }
  // MessageTransport::hand_over put the message of receive_into in its vector.
  void received_into(machine::SimTime sent) {
    received_ = true;
    received_sent_ = sent;
    wake();
  }
  // Blocks while a is running (until it is done or cancelled); false when the run was abandoned
  // meanwhile (a is then cancelled).
  bool wait_for_activity(Activity& a, const char* call, int peer);
  bool wait_in_line(Activity& a, const char* call, int peer);  // the same, inline (a receive's wait)

  int thread() const { return thread_; }
  bool finished = false;
  bool asleep = false;
  const char* blocked_call = nullptr;
  const WaitDescription* blocked_description = nullptr;  // await()'s, named in place of blocked_call
  int blocked_peer = -1;
  machine::SimTime blocked_since = 0;
  FiberContext fiber;
  SimProcess* joiner = nullptr;  // who waits in Thread::join for this thread

 protected:
  void close_link(std::int64_t handle) override;

 private:
  Request post_send(Link& link, std::span<const std::byte> data, bool synchronous);
  [[gnu::noinline]] bool charge_send_cpu(Link& link, std::size_t bytes);
  [[gnu::noinline, gnu::cold]] Request abandoned_send();
  Request post_receive(Link& link);
  // Posts a receive on link's end with req (fresh or rearmed) and matches it with an arrived message.
  void post_receive(Request& req, Link& link);
  void post_receive(Request& req, LinkEnd& e, const Link& link);  // e: link's end, checked
  // A blocking receive into `into` on e, untraced and uncharged, whose message is not there yet:
  // posted without a request (see PostedReceive), then waits for it.
  void receive_into(LinkEnd& e, Bytes& into);

  // The request a blocking receive waits on, reused from one receive to the next: once it is over
  // only this process holds it, and it needs neither the pool nor a reset of every field.
  Request& blocking_receive();
  // The request of an isend or send, reused the same way: once the program has dropped its copy
  // and the message is delivered, only this process holds it. Else one from the pool, kept next.
  Request send_request();
  LinkEnd& end_of(const Link& link, const char* call);
  // A request that is over already (a delivered isend) costs a test; waiting for one still
  // running is out of line.
  void wait_for(RequestState& r, const char* call, TraceKind kind);
  void wait_for_running(RequestState& r, const char* call, TraceKind kind);
  // The same wait in line, for a blocking receive, which usually has to wait: no call, no
  // second frame.
  void wait_for_receive(RequestState& r);
  void wait_running(RequestState& r, const char* call, TraceKind kind);
  [[gnu::noinline]] void trace_wait(const RequestState& r, const char* call, TraceKind kind, machine::SimTime start);
  // Holds one of the node's CPUs for `duration` (compute and the CPU side of communication share
  // them); false when the run was abandoned meanwhile.
  bool occupy_cpu(machine::SimTime duration, std::string_view label);
  // compute() and compute_in_comm(): the same charge, counted as compute or as communication.
  void charge_ops(std::span<const OpCount> ops, bool as_comm);
  // The machine's [comm_cpu] cost of one operation: `fixed` plus the copy of `bytes`, as
  // communication time.
  bool charge_comm_cpu(machine::SimTime fixed, std::int64_t bytes, std::string_view label);
  void charge_receive_cpu(RequestState& r);  // its tests inline (the same unit), the charge not
  void charge_receive_cpu_now(RequestState& r);
  Simulation& sim_;
  int id_;
  int thread_;
  // This processor's statistics and node, looked up once: the simulation sizes both tables
  // before any process exists and never resizes them.
  ProcessorStats& stats_;
  int node_;
  machine::Node& cpu_;  // its node's (sim_.nodes is a deque: no index on every charge)
  Request blocking_receive_;  // empty until the first blocking receive; see blocking_receive()
  Request send_request_;      // empty until the first send; see send_request()
  bool received_ = false;     // receive_into's message has arrived
  machine::SimTime received_sent_ = 0;  // and when its sender sent it
};

}  // namespace gcsim::parix::detail
