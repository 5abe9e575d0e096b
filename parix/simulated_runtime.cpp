#include "parix/simulated_runtime.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

#include <boost/fiber/all.hpp>
#include <fmt/format.h>

#include "machine/connection_service.hpp"
#include "machine/kernel.hpp"
#include "machine/mesh.hpp"
#include "machine/network_model.hpp"
#include "machine/node.hpp"
#include "machine/trace.hpp"
#include "parix/fiber_stack.hpp"

namespace gcsim::parix {
namespace {

using machine::Kernel;
using machine::TraceKind;
using machine::TraceRecord;

// Thrown into a blocked fiber to unwind it when the run is abandoned (deadlock or an error
// elsewhere). Deliberately not a std::exception, so application handlers do not catch it.
struct Cancelled {};

class Simulation;

// A message on its way or waiting in a link's queue.
struct Message {
  Bytes data;
  std::shared_ptr<RequestState> send;  // completed when received (synchronous) or delivered
  bool synchronous = false;
  std::int64_t id = 0;
  std::int64_t link_seq = 0;  // position on its link: a link delivers in sending order
  std::int64_t dst_end = -1;  // the link end it goes to
  int src = -1;
  machine::SimTime sent = 0;
};

// One end of a virtual link.
struct LinkEnd {
  int owner = -1;
  int peer = -1;
  std::int64_t peer_end = -1;
  bool open = true;
  std::int64_t sent = 0;                                 // messages sent from this end
  std::int64_t delivered = 0;                            // messages delivered to this end
  std::map<std::int64_t, Message> early;                 // arrived before a predecessor
  std::deque<Message> arrived;                           // delivered, not yet received
  std::deque<std::shared_ptr<RequestState>> receives;    // posted, waiting for a message
};

class SimProcess final : public Processor {
 public:
  SimProcess(Simulation& sim, int id, int thread) : sim_(sim), id_(id), thread_(thread) {}
  ~SimProcess() override { drop_persistent_links(); }

  int id() const override;
  int count() const override;
  SimTime now() const override;
  void compute(std::span<const OpCount> ops) override;
  void use_memory(std::int64_t bytes) override;
  Link connect(int peer, int tag) override;
  void send(Link& link, std::span<const std::byte> data) override;
  Bytes recv(Link& link) override;
  Request isend(Link& link, std::span<const std::byte> data) override;
  Request irecv(Link& link) override;
  void wait(Request& r) override;
  std::size_t wait_any(std::span<Request* const> rs) override;
  Thread spawn(std::function<void(Processor&)> body) override;

  // Suspends this fiber until wake(); `call` and `peer` describe the wait for deadlock reports.
  void block(const char* call, int peer);
  void wake();

  int thread() const { return thread_; }
  bool finished = false;
  bool asleep = false;
  const char* blocked_call = nullptr;
  int blocked_peer = -1;
  machine::SimTime blocked_since = 0;
  boost::fibers::context* ctx = nullptr;
  SimProcess* joiner = nullptr;  // who waits in Thread::join for this thread

 protected:
  void close_link(std::int64_t handle) override;

 private:
  Request post_send(Link& link, std::span<const std::byte> data, bool synchronous);
  LinkEnd& end_of(const Link& link, const char* call);
  void wait_for(RequestState& r, const char* call, TraceKind kind);
  Simulation& sim_;
  int id_;
  int thread_;
};

class Simulation {
 public:
  explicit Simulation(const SimulationOptions& o)
      : config(o.nodes > 0 ? machine::with_nodes(o.config, o.nodes) : o.config),
        mesh(config.mesh_width, config.mesh_height),
        trace(o.trace, config.nodes, config.mesh_width, config.mesh_height),
        network(machine::make_network_model(o.network_model.empty() ? config.network_model : o.network_model,
                                            {kernel, mesh, config, trace.enabled() ? &trace : nullptr})),
        connections(config, mesh) {
    for (int n = 0; n < config.nodes; ++n) nodes.emplace_back(kernel, config.cpus_per_node, config.memory_bytes);
    stats.resize(config.nodes);
  }

  RunResult run(const std::function<void(Processor&)>& program);

  void launch(SimProcess* p, std::function<void(Processor&)> body) {
    ++runnable;
    ++live;
    fibers.emplace_back(boost::fibers::launch::post, std::allocator_arg,
                        FiberStack(kStackBytes), [this, p, body = std::move(body)] {
                          p->ctx = boost::fibers::context::active();
                          try {
                            body(*p);
                          } catch (const Cancelled&) {
                          } catch (...) {
                            if (!failure) failure = std::current_exception();
                          }
                          p->drop_persistent_links();
                          finish(p);
                        });
  }

  void finish(SimProcess* p) {
    p->finished = true;
    auto& s = stats[p->id()];
    s.finish = std::max(s.finish, kernel.now());
    if (p->joiner) p->joiner->wake();
    --runnable;
    --live;
  }

  std::int64_t new_link_end() {
    links.emplace_back();
    return static_cast<std::int64_t>(links.size()) - 1;
  }

  void deliver(Message&& m);
  // Messages in the network wait in a slab, so callbacks can refer to them by index.
  std::int64_t park(Message&& m) {
    if (free_slots.empty()) {
      in_flight.push_back(std::move(m));
      return static_cast<std::int64_t>(in_flight.size()) - 1;
    }
    const std::int64_t slot = free_slots.back();
    free_slots.pop_back();
    in_flight[slot] = std::move(m);
    return slot;
  }
  Message unpark(std::int64_t slot) {
    Message m = std::move(in_flight[slot]);
    free_slots.push_back(slot);
    return m;
  }
  void accept(LinkEnd& e, Message&& m);
  void complete(const std::shared_ptr<RequestState>& r) {
    r->done = true;
    if (r->waiter) static_cast<SimProcess*>(r->waiter)->wake();
  }


  std::string deadlock_report() const;

  static constexpr std::size_t kStackBytes = 1 << 20;

  machine::MachineConfig config;
  machine::Kernel kernel;
  machine::Mesh mesh;
  machine::TraceWriter trace;
  std::unique_ptr<machine::NetworkModel> network;
  machine::ConnectionService connections;
  std::deque<machine::Node> nodes;
  std::vector<ProcessorStats> stats;
  std::deque<LinkEnd> links;
  std::vector<Message> in_flight;
  std::vector<std::int64_t> free_slots;
  std::vector<std::unique_ptr<SimProcess>> processes;
  std::vector<boost::fibers::fiber> fibers;
  // Connections waiting for their other end: (from, to, tag) -> the waiting ends, in call order.
  struct PendingConnect {
    SimProcess* who;
    std::int64_t* result;
    machine::SimTime since;
  };
  std::map<std::tuple<int, int, int>, std::deque<PendingConnect>> pending_connects;
  std::int64_t next_message = 0;
  int runnable = 0;
  int live = 0;
  bool cancelling = false;
  std::exception_ptr failure;
  boost::fibers::context* main_ctx = nullptr;
};

// ---- SimProcess ------------------------------------------------------------------------------

int SimProcess::id() const { return id_; }
int SimProcess::count() const { return sim_.config.nodes; }
SimTime SimProcess::now() const { return sim_.kernel.now(); }

void SimProcess::block(const char* call, int peer) {
  if (sim_.cancelling) {
    if (std::uncaught_exceptions() == 0) throw Cancelled{};
    return;  // already unwinding: let the caller give up
  }
  blocked_call = call;
  blocked_peer = peer;
  blocked_since = sim_.kernel.now();
  asleep = true;
  --sim_.runnable;
  ctx->suspend();
  blocked_call = nullptr;
  if (sim_.cancelling && std::uncaught_exceptions() == 0) throw Cancelled{};
}

void SimProcess::wake() {
  if (!asleep) return;
  asleep = false;
  ++sim_.runnable;
  boost::fibers::context::active()->schedule(ctx);
}

void SimProcess::compute(std::span<const OpCount> ops) {
  machine::SimTime duration = 0;
  auto& s = sim_.stats[id_];
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
  const machine::SimTime start = sim_.kernel.now();
  bool done = false;
  sim_.nodes[id_].compute(duration, [this, &done] {
    done = true;
    wake();
  });
  while (!done) {
    block("compute", -1);
    if (sim_.cancelling) return;
  }
  s.compute += duration;
  if (sim_.trace.enabled()) {
    sim_.trace.record({TraceKind::compute, id_, -1, start, sim_.kernel.now(), 0, -1,
                       ops.size() == 1 ? ops[0].op : std::string_view("compute"), thread_});
  }
}

void SimProcess::use_memory(std::int64_t bytes) {
  machine::Node& node = sim_.nodes[id_];
  if (!node.use_memory(bytes)) {
    throw ParixError(fmt::format("processor {}: out of memory: {} bytes in use + {} requested > {} bytes on the node",
                                 id_, node.memory_used(), bytes, node.memory_bytes()));
  }
}

Link SimProcess::connect(int peer, int tag) {
  if (peer < 0 || peer >= count()) {
    throw ParixError(fmt::format("processor {}: connect to processor {}, which does not exist (0..{})", id_, peer, count() - 1));
  }
  if (peer == id_) throw ParixError(fmt::format("processor {}: connect to itself; a link needs two processors", id_));
  const machine::SimTime start = sim_.kernel.now();
  auto& other_side = sim_.pending_connects[{peer, id_, tag}];
  std::int64_t mine = -1;
  if (!other_side.empty()) {
    Simulation::PendingConnect other = other_side.front();
    other_side.pop_front();
    const std::int64_t a = sim_.new_link_end(), b = sim_.new_link_end();
    LinkEnd& ea = sim_.links[a];
    LinkEnd& eb = sim_.links[b];
    ea.owner = id_, ea.peer = peer, ea.peer_end = b;
    eb.owner = peer, eb.peer = id_, eb.peer_end = a;
    const machine::SimTime up = sim_.connections.set_up(id_, peer, start);
    bool done = false;
    std::int64_t* theirs = other.result;
    SimProcess* them = other.who;
    const machine::SimTime their_start = other.since;
    sim_.kernel.at(up, [this, &done, theirs, them, b] {
      done = true;
      *theirs = b;
      them->wake();
      wake();
    });
    while (!done) {
      block("connect", peer);
      if (sim_.cancelling) return {};
    }
    mine = a;
    sim_.stats[peer].connections += 1;
    sim_.stats[id_].connections += 1;
    if (sim_.trace.enabled()) {
      sim_.trace.record({TraceKind::connect, peer, id_, their_start, up, 0, -1, "connect", them->thread()});
      sim_.trace.record({TraceKind::connect, id_, peer, start, up, 0, -1, "connect", thread_});
    }
  } else {
    sim_.pending_connects[{id_, peer, tag}].push_back({this, &mine, start});
    while (mine < 0) {
      block("connect", peer);
      if (sim_.cancelling) return {};
    }
  }
  const machine::SimTime took = sim_.kernel.now() - start;
  sim_.stats[id_].comm += took;
  sim_.stats[id_].connect += took;
  return Link(this, peer, tag, mine);
}

void SimProcess::close_link(std::int64_t handle) {
  if (handle >= 0 && handle < static_cast<std::int64_t>(sim_.links.size())) sim_.links[handle].open = false;
}

LinkEnd& SimProcess::end_of(const Link& link, const char* call) {
  if (!link.valid()) throw ParixError(fmt::format("processor {}: {} on a link that is not open", id_, call));
  LinkEnd& e = sim_.links.at(link.handle());
  if (e.owner != id_) throw ParixError(fmt::format("processor {}: {} on a link owned by processor {}", id_, call, e.owner));
  return e;
}

Request SimProcess::post_send(Link& link, std::span<const std::byte> data, bool synchronous) {
  LinkEnd& e = end_of(link, "send");
  auto req = std::make_shared<RequestState>();
  req->link = link.handle();
  req->peer = e.peer;
  Message m;
  m.data.assign(data.begin(), data.end());
  m.send = req;
  m.synchronous = synchronous;
  m.id = sim_.next_message++;
  m.link_seq = e.sent++;
  m.src = id_;
  m.sent = sim_.kernel.now();
  auto& s = sim_.stats[id_];
  ++s.messages_sent;
  s.bytes_sent += static_cast<std::int64_t>(data.size());
  m.dst_end = e.peer_end;
  // The arrival callback captures only (simulation, slot): small enough for std::function to
  // store inline, which keeps the per-message cost free of extra allocations.
  const std::int64_t slot = sim_.park(std::move(m));
  sim_.network->transfer(id_, e.peer, static_cast<std::int64_t>(data.size()),
                         [sim = &sim_, slot] { sim->deliver(sim->unpark(slot)); });
  return Request(req);
}

void Simulation::deliver(Message&& m) {
  LinkEnd& e = links[m.dst_end];
  if (m.link_seq != e.delivered) {
    // A shorter message overtook a longer one in the network; the link keeps sending order.
    e.early.emplace(m.link_seq, std::move(m));
    return;
  }
  ++e.delivered;
  accept(e, std::move(m));
  for (auto it = e.early.find(e.delivered); it != e.early.end(); it = e.early.find(e.delivered)) {
    Message next = std::move(it->second);
    e.early.erase(it);
    ++e.delivered;
    accept(e, std::move(next));
  }
}

void Simulation::accept(LinkEnd& e, Message&& m) {
  if (trace.enabled()) {
    trace.record({TraceKind::message, m.src, e.owner, m.sent, kernel.now(), static_cast<std::int64_t>(m.data.size()),
                  m.id, "message"});
  }
  if (!m.synchronous) complete(m.send);
  if (!e.receives.empty()) {
    std::shared_ptr<RequestState> r = std::move(e.receives.front());
    e.receives.pop_front();
    r->data = std::move(m.data);
    if (m.synchronous) complete(m.send);
    complete(r);
  } else {
    e.arrived.push_back(std::move(m));
  }
}

Request SimProcess::isend(Link& link, std::span<const std::byte> data) { return post_send(link, data, false); }

void SimProcess::send(Link& link, std::span<const std::byte> data) {
  Request r = post_send(link, data, true);
  wait_for(*r.state(), "send", TraceKind::send);
}

Request SimProcess::irecv(Link& link) {
  LinkEnd& e = end_of(link, "recv");
  auto req = std::make_shared<RequestState>();
  req->is_receive = true;
  req->link = link.handle();
  req->peer = e.peer;
  if (!e.arrived.empty()) {
    Message m = std::move(e.arrived.front());
    e.arrived.pop_front();
    req->data = std::move(m.data);
    req->done = true;
    if (m.synchronous) sim_.complete(m.send);
  } else {
    e.receives.push_back(req);
  }
  return Request(req);
}

Bytes SimProcess::recv(Link& link) {
  Request r = irecv(link);
  wait_for(*r.state(), "recv", TraceKind::recv);
  return r.take();
}

void SimProcess::wait_for(RequestState& r, const char* call, TraceKind kind) {
  const machine::SimTime start = sim_.kernel.now();
  while (!r.done) {
    r.waiter = this;
    block(call, r.peer);
    r.waiter = nullptr;
    if (sim_.cancelling) return;
  }
  const machine::SimTime end = sim_.kernel.now();
  sim_.stats[id_].comm += end - start;
  if (sim_.trace.enabled() && end > start) {
    sim_.trace.record({kind, id_, r.peer, start, end, static_cast<std::int64_t>(r.data.size()), -1, call, thread_});
  }
}

void SimProcess::wait(Request& r) {
  if (!r.valid()) throw ParixError(fmt::format("processor {}: wait on an empty request", id_));
  wait_for(*r.state(), "wait", TraceKind::wait);
}

std::size_t SimProcess::wait_any(std::span<Request* const> rs) {
  if (rs.empty()) throw ParixError(fmt::format("processor {}: wait_any on no requests", id_));
  const machine::SimTime start = sim_.kernel.now();
  auto first_done = [&]() -> std::size_t {
    for (std::size_t i = 0; i < rs.size(); ++i) {
      if (!rs[i]->valid()) throw ParixError(fmt::format("processor {}: wait_any on an empty request", id_));
      if (rs[i]->done()) return i;
    }
    return rs.size();
  };
  std::size_t i;
  while ((i = first_done()) == rs.size()) {
    for (Request* r : rs) r->state()->waiter = this;
    block("wait_any", rs.size() == 1 ? rs[0]->state()->peer : -1);
    for (Request* r : rs) r->state()->waiter = nullptr;
    if (sim_.cancelling) return 0;
  }
  const machine::SimTime end = sim_.kernel.now();
  sim_.stats[id_].comm += end - start;
  if (sim_.trace.enabled() && end > start) {
    sim_.trace.record({TraceKind::wait, id_, rs[i]->state()->peer, start, end, 0, -1, "wait_any", thread_});
  }
  return i;
}

Thread SimProcess::spawn(std::function<void(Processor&)> body) {
  const int thread = static_cast<int>(std::count_if(sim_.processes.begin(), sim_.processes.end(),
                                                    [&](const auto& p) { return p->id() == id_; }));
  sim_.processes.push_back(std::make_unique<SimProcess>(sim_, id_, thread));
  SimProcess* t = sim_.processes.back().get();
  sim_.launch(t, std::move(body));
  return Thread([this, t] {
    while (!t->finished) {
      t->joiner = this;
      block("join", id_);
      if (sim_.cancelling) return;
    }
  });
}

// ---- Simulation ------------------------------------------------------------------------------

std::string Simulation::deadlock_report() const {
  std::ostringstream os;
  os << "deadlock at simulated time " << machine::to_milliseconds(kernel.now())
     << " ms: every processor is blocked and no event is pending\n";
  for (const auto& p : processes) {
    if (p->finished) continue;
    os << "  processor " << p->id();
    if (p->thread() > 0) os << " (thread " << p->thread() << ")";
    os << ": blocked in " << (p->blocked_call ? p->blocked_call : "?");
    if (p->blocked_peer >= 0) {
      os << (std::string_view(p->blocked_call ? p->blocked_call : "") == "send" ? " to" : " on") << " processor "
         << p->blocked_peer;
    }
    os << " since " << machine::to_milliseconds(p->blocked_since) << " ms\n";
  }
  return os.str();
}

RunResult Simulation::run(const std::function<void(Processor&)>& program) {
  const auto wall_start = std::chrono::steady_clock::now();
  main_ctx = boost::fibers::context::active();
  for (int i = 0; i < config.nodes; ++i) processes.push_back(std::make_unique<SimProcess>(*this, i, 0));
  for (int i = 0; i < config.nodes; ++i) launch(processes[i].get(), program);

  bool deadlock = false;
  for (;;) {
    while (runnable > 0) boost::this_fiber::yield();  // let every woken fiber run until it blocks
    if (failure || live == 0) break;
    if (!kernel.step()) {
      deadlock = true;
      break;
    }
  }
  std::string report;
  if (deadlock) report = deadlock_report();
  if (deadlock || failure) {
    // Unwind every blocked fiber so that their stacks are released cleanly.
    cancelling = true;
    for (auto& p : processes) p->wake();
    while (live > 0) boost::this_fiber::yield();
  } else {
    kernel.run();  // messages still in flight after the last processor returned
  }
  for (auto& f : fibers) f.join();
  trace.close();
  if (failure) std::rethrow_exception(failure);
  if (deadlock) throw DeadlockError(report);

  RunResult r;
  r.model = std::string(network->name());
  r.config_name = config.name;
  r.nodes = config.nodes;
  r.events = kernel.events_processed();
  r.processors = stats;
  for (const auto& s : stats) r.makespan = std::max(r.makespan, s.finish);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return r;
}

}  // namespace

RunResult run_simulated(const SimulationOptions& options, const std::function<void(Processor&)>& program) {
  Simulation sim(options);
  return sim.run(program);
}

}  // namespace gcsim::parix
