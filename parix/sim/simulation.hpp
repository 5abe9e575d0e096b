#pragma once
// The simulated runtime's state, shared by its units: processes (SimProcess, one per processor and
// thread, each a fiber), the links between them and the Simulation that owns the kernel, the
// network and the machine. Internal to parix/: applications use parix/sim/simulated_runtime.hpp.
#include <chrono>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "machine/connection_service.hpp"
#include "machine/kernel.hpp"
#include "machine/mesh.hpp"
#include "machine/network_model.hpp"
#include "machine/node.hpp"
#include "machine/ring_buffer.hpp"
#include "machine/trace.hpp"
#include "parix/sim/activity.hpp"
#include "parix/sim/connection_matcher.hpp"
#include "parix/sim/fiber_processes.hpp"
#include "parix/sim/in_order_delivery.hpp"
#include "parix/sim/link_table.hpp"
#include "parix/sim/payload_pool.hpp"
#include "parix/sim/request_pool.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "parix/sim/stable_vector.hpp"

namespace gcsim::parix::detail {

using machine::Kernel;
using machine::TraceKind;
using machine::TraceRecord;

// Thrown into a blocked fiber to unwind it when the run is abandoned (deadlock or an error
// elsewhere). Deliberately not a std::exception, so application handlers do not catch it.
struct Cancelled {};

class Simulation;
struct LinkEnd;

// A message on its way or waiting in a link's queue.
struct Message {
  Bytes data;
  Request send;  // completed when received (synchronous) or delivered;
                // cancelled: the link drops the message on arrival
  bool synchronous = false;
  std::int64_t id = 0;
  std::int64_t link_seq = 0;  // position on its link: a link delivers in sending order
  LinkEnd* dst = nullptr;  // the link end it goes to (its pair is not reused while a message travels to it)
  int src = -1;
  machine::SimTime sent = 0;
};

// A message waiting in its link end's queue: what a receive needs of it, half a Message, which
// the queue moves in and, while it grows, around.
struct HeldMessage {
  Bytes data;
  Request send;  // a synchronous send, completed when received (null: asynchronous, completed on arrival)
  bool synchronous = false;
};

class SimProcess;

// A receive waiting on its link end: a request, or a blocking receive into the caller's vector
// (untraced, no [comm_cpu] charge: nothing asks a request's size), which needs none. Its message is
// swapped straight into that vector and its process woken (Simulation::hand_over); the caller's
// old storage stays with the message's slot for the next message sent in it.
struct PostedReceive {
  Request request;                 // null for a receive into a vector
  Bytes* into = nullptr;           // the vector, or null
  SimProcess* receiver = nullptr;  // whom to wake, or null
};

// One end of a virtual link.
struct LinkEnd {
  int owner = -1;
  int peer = -1;
  std::int64_t peer_end = -1;
  LinkEnd* peer_at = nullptr;  // the end of peer_end (ends never move)
  bool open = true;
  std::int64_t sent = 0;                                 // messages sent from this end
  InOrderDelivery<Message> order;                        // holds messages that overtook a predecessor
  machine::RingBuffer<HeldMessage> arrived;              // delivered, not yet received
  machine::RingBuffer<PostedReceive> receives;           // posted, waiting for a message
  // Nothing the peer sent is still travelling or held, and nothing waits here: the slot may go.
  bool idle(const LinkEnd& peer) const {
    return peer.sent == order.delivered() && arrived.empty() && receives.empty();
  }
};

class SimProcess final : public Processor, public Waiter {
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

  // Suspends this fiber until wake(); `call` and `peer` describe the wait for deadlock reports.
  void block(const char* call, int peer);
  void wake() override;
  // Simulation::hand_over put the message of receive_into in its vector.
  void received_into() {
    received_ = true;
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
  Request blocking_receive_;  // empty until the first blocking receive; see blocking_receive()
  Request send_request_;      // empty until the first send; see send_request()
  bool received_ = false;     // receive_into's message has arrived
};

// options.placement checked to be a permutation of 0..nodes-1; identity when empty.
std::vector<int> checked_placement(const std::vector<int>& placement, int nodes);

class Simulation {
 public:
  explicit Simulation(const SimulationOptions& o)
      : config(o.config),
        mesh(config.mesh_width, config.mesh_height),
        trace(o.trace, config.nodes, config.mesh_width, config.mesh_height),
        network(machine::make_network_model(config.network_model,
                                            {kernel, mesh, config, trace.enabled() ? &trace : nullptr})),
        connections(config, mesh),
        fibers(static_cast<std::size_t>(config.fiber_stack_bytes)) {
    for (int n = 0; n < config.nodes; ++n) {
      nodes.emplace_back(kernel, config.cpus_per_node, config.memory_bytes, o.memory_limit);
      in_flight_kind = nodes.back().memory().kind(kMessagesInFlight);
      received_kind = nodes.back().memory().kind(kMessagesReceived);
    }
    stats.resize(config.nodes);
    node_of = checked_placement(o.placement, config.nodes);
    for (int p = 0; p < config.nodes; ++p) memory_of.push_back(&nodes[node_of[p]].memory());
  }

  RunResult run(const std::function<void(Processor&)>& program);
  // The run's figures; an interrupted run's makespan is the kernel's clock when it stopped.
  RunResult result(std::chrono::steady_clock::time_point wall_start, bool interrupted) const;

  // Starts p's fiber; throws, with nothing started, if no fiber stack can be mapped.
  void launch(SimProcess* p, std::function<void(Processor&)> body) {
    fibers.launch(p->fiber, [this, p, body = std::move(body)] {
      try {
        if (!cancelling) body(*p);  // a run abandoned before this fiber first ran skips it
      } catch (const Cancelled&) {
      } catch (...) {
        if (!failure) failure = std::current_exception();
      }
      p->drop_persistent_links();
      finish(p);
    });
    ++live;
  }

  void finish(SimProcess* p) {
    p->finished = true;
    auto& s = stats[p->id()];
    s.finish = std::max(s.finish, kernel.now());
    if (p->joiner) p->joiner->wake();
    --live;
  }

  // The message in slot m arrived: delivered in place (no copy of it), then the slot is free.
  void deliver(Message& m);
  // Messages in the network wait in slots that never move, so callbacks can refer to them by
  // address. A free slot for the next one, which the caller fills in place: its request is null
  // (moved on or reset by deliver), its payload empty or a receiver's old storage (hand_over), to
  // be overwritten.
  Message& take_slot() {
    if (free_slots.empty()) [[unlikely]] return in_flight.emplace_back();
    Message& m = *free_slots.back();
    free_slots.pop_back();
    return m;
  }
  // A message delivered in order to its link end: to a waiting receive, else to the end's queue.
  void accept(LinkEnd& e, Message&& m);
  [[gnu::noinline]] void accept_slow(LinkEnd& e, Message&& m);  // withdrawn or traced
  // Accepts e's held messages that are now in order (one arrived that they had overtaken). Out of
  // line: most links never hold any.
  [[gnu::noinline]] void release_held(LinkEnd& e);
  // Completes an asynchronous send, then gives m to e's first waiting receive, or holds it.
  [[gnu::always_inline]] inline void hand_over(LinkEnd& e, Message&& m);
  // Queues m at e until a receive takes it (its send, if asynchronous, completed already).
  [[gnu::always_inline]] inline void hold(LinkEnd& e, Message&& m);
  // Declares memory on the node of `processor` (negative: releases). Returns "" when granted,
  // else the out-of-memory report to raise; the first overrun of a run that only warns is kept
  // in memory_warning.
  std::string use_memory(int processor, std::int64_t bytes, std::string_view kind);
  std::string use_memory(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind);
  // The same by handle without building a report, the form the runtime uses on every message:
  // true when granted; when refused, refusal() is the report. Inline: it runs twice per message.
  bool declare_memory(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    machine::NodeMemory& memory = *memory_of[processor];
    if (!memory.use(bytes, kind)) return false;
    if (memory.over() && memory_warning.empty()) memory_warning = memory.report(processor, 0, memory.kind_name(kind));
    return true;
  }
  // The same for bytes > 0, a message's: within the node's memory in line (NodeMemory::add_within),
  // an overrun (refused, or granted with a warning) out of line.
  bool declare_message(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    if (memory_of[processor]->add_within(bytes, kind)) [[likely]] return true;
    return declare_beyond(processor, bytes, kind);
  }
  [[gnu::noinline]] bool declare_beyond(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    machine::NodeMemory& memory = *memory_of[processor];
    if (!memory.add(bytes, kind)) return false;
    if (memory.over() && memory_warning.empty()) memory_warning = memory.report(processor, 0, memory.kind_name(kind));
    return true;
  }
  // Gives back bytes > 0 declared before. Never fails, and needs no warning: a node over its
  // memory got there by a declaration, which kept the first warning.
  void release_memory(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    memory_of[processor]->release(bytes, kind);
  }
  // The bytes of a message that arrived, declared in flight on its sender's node when it was sent
  // (which threw when refused, so every message in flight holds its bytes there).
  void release_in_flight(const Message& m) {
    memory_of[m.src]->give_back(static_cast<std::int64_t>(m.data.size()), in_flight_kind);
  }
  std::string refusal(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) const {
    const machine::NodeMemory& memory = *memory_of[processor];
    return memory.report(processor, bytes, memory.kind_name(kind));
  }
  void complete(const Request& r) { r.state()->complete(); }
  // A blocking receive by processor `receiver` that finds e's front message there: what the
  // receive's request would do with it, without the request (SimProcess::post_receive, then
  // Request::take_into). into's old storage goes back to the pool.
  void take_held(LinkEnd& e, int receiver, Bytes& into) {
    HeldMessage& m = e.arrived.front();
    if (!m.data.empty()) release_memory(receiver, static_cast<std::int64_t>(m.data.size()), received_kind);
    into.swap(m.data);
    if (m.synchronous) complete(m.send);
    m.send = Request();
    e.arrived.drop_front();
    payloads.give(std::move(m.data));  // leaves the slot's payload empty
  }


  std::string deadlock_report() const;

  // The most storage a message's slot keeps from a receiver's old vector (see PostedReceive);
  // more goes back to the pool, which bounds what it keeps.
  static constexpr std::size_t kSlotKeepsBytes = 4096;
  RequestPool requests;      // first member: outlives every request the others hold
  PayloadPool payloads;      // messages' storage, recycled (parix/sim/payload_pool.hpp)
  machine::MachineConfig config;
  // Whether [comm_cpu] charges anything: asked on every send and receive.
  const bool charges_comm_cpu = config.comm_cpu.any();
  std::vector<int> node_of;  // processor -> node (SimulationOptions::placement)
  // processor -> its node's memory: what every message declares to, without the deque's lookup.
  std::vector<machine::NodeMemory*> memory_of;
  machine::Kernel kernel;
  machine::Mesh mesh;
  machine::TraceWriter trace;
  std::unique_ptr<machine::NetworkModel> network;
  machine::ConnectionService connections;
  std::deque<machine::Node> nodes;
  // Node memory the runtime itself holds for messages, declared on every message. Registered first
  // on every node, so each kind has the same handle on all of them.
  static constexpr std::string_view kMessagesInFlight = "messages in flight";
  static constexpr std::string_view kMessagesReceived = "messages received";
  machine::NodeMemory::Kind in_flight_kind = 0;
  machine::NodeMemory::Kind received_kind = 0;
  std::vector<ProcessorStats> stats;
  LinkTable<LinkEnd> links;
  StableVector<Message> in_flight;  // slots of the messages in flight, at most the run's peak
  std::vector<Message*> free_slots;
  std::vector<std::unique_ptr<SimProcess>> processes;
  FiberPool fibers;
  // A connect call waiting for its other end.
  struct PendingConnect {
    SimProcess* who;
    std::int64_t* result;  // the link end it gets
    Activity* set_up;      // completed when the link is up
    machine::SimTime since;
  };
  ConnectionMatcher<PendingConnect> connect_matcher;
  std::int64_t next_message = 0;
  int live = 0;
  bool cancelling = false;
  std::exception_ptr failure;
  std::string memory_warning;
};

}  // namespace gcsim::parix::detail
