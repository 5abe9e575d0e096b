// The rank's engine: communicators, requests, the eager and rendezvous protocols and matching.
#include "apps/mpi/runtime/rank.hpp"

#include <algorithm>

#include "apps/mpi/runtime/rank_letters.hpp"
#include "apps/mpi/runtime/error_routing.hpp"
#include "apps/mpi/type_transfer.hpp"
#include "parix/sim/fiber_stack.hpp"

namespace gcsim::mpi_layer {
namespace {

thread_local Rank* running = nullptr;

parix::Mailbox& mailbox_or_fail(parix::Processor& p) {
  parix::Mailbox* box = parix::mailbox_of(p);
  if (!box) fail(MPI_ERR_OTHER, "this backend has no addressed messages: MPI programs run on the simulated backend");
  return *box;
}

// The communicator rank of world rank `world` among members: at its own index in MPI_COMM_WORLD
// and its duplicates (found at once), else searched (members are distinct).
int rank_in(const std::vector<int>& members, int world) {
  const auto at = static_cast<std::size_t>(world);
  if (at < members.size() && members[at] == world) return world;
  return static_cast<int>(std::find(members.begin(), members.end(), world) - members.begin());
}

std::shared_ptr<const std::vector<int>> world_members(int size) {
  std::vector<int> world(static_cast<std::size_t>(size));
  for (std::size_t i = 0; i < world.size(); ++i) world[i] = static_cast<int>(i);
  return std::make_shared<const std::vector<int>>(std::move(world));
}

}  // namespace

Rank::Rank(parix::Processor& processor, const machine::MachineConfig::Mpi& costs, std::shared_ptr<const std::vector<int>> world)
    : processor_(processor), mailbox_(mailbox_or_fail(processor)), name_("rank " + std::to_string(processor.id())), costs_(costs) {
  registry_.world_rank = processor.id();
  if (!world) world = world_members(processor.count());
  if (static_cast<int>(world->size()) != processor.count()) fail(MPI_ERR_INTERN, "the world's members are not the run's ranks");
  comms_[MPI_COMM_WORLD] = Communicator{std::move(world), processor.id(), 2, 0, nullptr};
  comms_[MPI_COMM_SELF] =
      Communicator{std::make_shared<const std::vector<int>>(std::vector<int>{processor.id()}), 0, 4, 0, nullptr};
  comms_[MPI_COMM_WORLD].handle = MPI_COMM_WORLD;
  comms_[MPI_COMM_SELF].handle = MPI_COMM_SELF;
  world_ = &comms_[MPI_COMM_WORLD];
  registry_.errors = &runtime_error_router();
}

Rank& Rank::current() {
  if (!running) fail(MPI_ERR_OTHER, "no MPI rank runs here: start the program with gcsim mpirun");
  running->program_ran_ = true;  // every MPI call of the program comes here first
  running->progress_due_ = true;
  return *running;
}

void Rank::install() {
  running = this;
  progress_due_ = true;  // the fiber resumes: time passed, letters may have arrived
  install_registry(&registry_);
  parix::describe_running_stack(name_.c_str(), "raise it with gcsim mpirun --stack-size (default 8M)");
}

Communicator& Rank::comm(MPI_Comm handle) {
  if (handle == MPI_COMM_WORLD) {  // most calls' (never freed): no look-up
    registry_.call.name_target(handle);
    return *world_;
  }
  const auto it = comms_.find(handle);
  if (it == comms_.end()) {
    fail(MPI_ERR_COMM, handle == MPI_COMM_NULL ? "MPI_COMM_NULL is not a communicator" : "invalid or freed communicator");
  }
  registry_.call.name_target(handle);
  return it->second;
}

MPI_Comm Rank::add_comm(Communicator c) {
  const MPI_Comm h = next_comm_++;
  c.handle = h;
  comms_.emplace(h, std::move(c));
  return h;
}

void Rank::free_comm(MPI_Comm handle) {
  if (handle == MPI_COMM_WORLD || handle == MPI_COMM_SELF) fail(MPI_ERR_COMM, "cannot free a predefined communicator");
  const auto it = comms_.find(handle);
  if (it == comms_.end()) fail(MPI_ERR_COMM, "invalid communicator");
  for (const auto& schedule : schedules_) {  // its schedule reads the communicator until it ends
    if (!schedule->finished() && operation(schedule->request()).context == it->second.collective_context()) {
      fail(MPI_ERR_COMM, "a non-blocking collective on it is still in flight (complete it first)");
    }
  }
  comms_.erase(it);
}

std::string Rank::comm_name(MPI_Comm handle) {
  if (handle == MPI_COMM_WORLD) return "MPI_COMM_WORLD";
  if (handle == MPI_COMM_SELF) return "MPI_COMM_SELF";
  return "comm " + std::to_string(handle);
}

MPI_Request Rank::add_operation(Operation op) {
  progress_due_ = true;
  auto [h, slot] = operations_.add();
  slot = std::move(op);
  return h;
}

MPI_Request Rank::start_null(std::string call) {
  Operation op;
  op.call = CallText::of(std::move(call));
  op.done = true;
  op.charged = true;
  op.status.MPI_SOURCE = MPI_PROC_NULL;
  op.status.MPI_TAG = MPI_ANY_TAG;
  return add_operation(std::move(op));
}

Operation& Rank::operation(MPI_Request handle) {
  Operation* op = operations_.find(handle);
  if (!op) fail(MPI_ERR_REQUEST, "invalid or freed request");
  registry_.call.name_target(op->comm);
  return *op;
}

void Rank::leave_cpu() {
  if (!program_ran_ || !before_switch) return;
  program_ran_ = false;
  before_switch();
}

void Rank::charge(std::int64_t bytes) {
  const machine::SimTime d = costs_.call_overhead + machine::from_seconds(costs_.seconds_per_byte * static_cast<double>(bytes));
  if (d <= 0) return;
  leave_cpu();
  mailbox_.occupy(d, call_span.label("mpi_overhead"), true);
  install();
}

void Rank::charge_reduction(std::size_t bytes) {
  const machine::SimTime d = machine::from_seconds(costs_.reduce_seconds_per_byte * static_cast<double>(bytes));
  if (d <= 0) return;
  leave_cpu();
  mailbox_.occupy(d, call_span.label("mpi_reduction"), true);
  install();
}

MPI_Request Rank::start_send(const Communicator& c, std::int64_t context, int dest, int tag,
                             std::span<const std::byte> payload, SendMode mode, CallText call, bool request_if_done) {
  progress_due_ = true;  // an operation done at once, or waiting for its clear-to-send
  const int peer = c.world_rank_of(dest);
  const auto size = static_cast<std::int64_t>(payload.size());
  name_call_span(call);
  call_span.involve(peer, false);
  call_span.add_sent(size);
  charge(size);
  const bool rendezvous = mode == SendMode::synchronous || (mode == SendMode::standard && size > costs_.eager_limit_bytes);
  if (!rendezvous) {
    mailbox_.send(peer, envelope(kEager, size, context, tag, 0), payload);
    if (!request_if_done) return MPI_REQUEST_NULL;  // complete, and nobody will ask
  }
  auto [h, op] = operations_.add();
  op.is_send = true;
  op.done = !rendezvous;
  op.call = std::move(call);
  op.comm = c.handle;
  op.context = context;
  op.tag = tag;
  op.peer_world = peer;
  if (!rendezvous) return h;
  op.payload.assign(payload.begin(), payload.end());
  mailbox_.send(peer, envelope(kRequestToSend, size, context, tag, h), {});
  return h;
}

MPI_Request Rank::start_recv(const Communicator& c, std::int64_t context, int source, int tag, void* buffer,
                             MPI_Count count, const Datatype& type, CallText call) {
  auto [h, op] = operations_.add();
  op.call = std::move(call);
  op.comm = c.handle;
  op.members = c.members;
  op.context = context;
  op.tag = tag;
  op.peer_world = source == MPI_ANY_SOURCE ? -1 : c.world_rank_of(source);
  op.buffer = buffer;
  op.count = count;
  if (is_predefined(type)) {
    op.type = &type;
  } else {
    op.owned_type = std::make_unique<const Datatype>(type);
    op.type = op.owned_type.get();
  }
  name_call_span(op.call);
  call_span.involve(op.peer_world, true);
  call_span.add_received(pack_size(count, type));
  posted_.push_back(h);
  progress_due_ = true;  // an arrived message may match it
  progress();  // an arrived message matches at once
  return h;
}

MPI_Request Rank::start_raw_recv(const Communicator& c, std::int64_t context, int source, int tag, std::span<std::byte> into) {
  auto [h, op] = operations_.add();
  op.call = CallText::collective_receive(source);
  op.members = c.members;
  op.context = context;
  op.tag = tag;
  op.peer_world = c.world_rank_of(source);
  op.raw = into;
  op.is_raw = true;
  call_span.involve(op.peer_world, true);
  call_span.add_received(static_cast<std::int64_t>(into.size()));
  posted_.push_back(h);
  progress_due_ = true;  // an arrived message may match it
  progress();
  return h;
}

void Rank::name_call_span(const CallText& call) {
  if (call.form == CallText::Form::point_to_point) call_span.name_literal(call.name);
  else if (call.text) call_span.describe(*call.text);
}

bool Rank::matches(const Operation& r, const Arrived& m) {
  return r.context == m.context && (r.peer_world < 0 || r.peer_world == m.source) && (r.tag == MPI_ANY_TAG || r.tag == m.tag);
}

void Rank::progress() {
  if (!progress_due_) return;
  progress_due_ = false;
  // Unexpected messages first match receives posted since they arrived.
  for (auto it = unexpected_.begin(); it != unexpected_.end();) {
    const auto r = std::find_if(posted_.begin(), posted_.end(), [&](MPI_Request h) { return matches(operations_.at(h), *it); });
    if (r == posted_.end()) {
      ++it;
      continue;
    }
    const MPI_Request h = *r;
    posted_.erase(r);
    Arrived m = std::move(*it);
    it = unexpected_.erase(it);
    match(operations_.at(h), h, std::move(m));
  }
  letters_.clear();
  mailbox_.collect(letters_);
  for (parix::Letter& l : letters_) on_letter(l);
  if (sends_on_wire_ > 0) {  // rendezvous sends whose data letter is on its way
    sends_on_wire_ = 0;
    for (const OperationTable::Entry& e : operations_) {
      Operation& op = *e.op;
      if (!op.is_send || op.done || !op.wire.valid()) continue;
      if (op.wire.test()) op.done = true;
      else ++sends_on_wire_;
    }
  }
  if (freed_live_ > 0) drop_freed();
  if (!schedules_.empty()) advance_collectives();
}

void Rank::on_letter(parix::Letter& l) {
  const auto& w = l.envelope.words;
  const std::int64_t kind = w[0] & 0xff;
  const std::int64_t size = w[0] >> 8;
  if (kind == kEager || kind == kRequestToSend) {
    on_message({l.source, w[1], static_cast<int>(w[2]), kind == kRequestToSend, size, w[3], std::move(l.data)});
  } else if (kind == kClearToSend) {
    Operation& s = operations_.at(w[3]);
    s.wire = mailbox_.post(s.peer_world, envelope(kData, 0, s.context, w[2], w[3]), s.payload);
    ++sends_on_wire_;
    s.payload = {};
  } else if (kind == kData) {
    Operation& r = operations_.at(w[2]);
    deliver(r, l.data);
    mailbox_.recycle(std::move(l.data));
  } else if (kind == kCancelAsk) {
    on_cancel_asked(l);
  } else if (kind == kCancelAnswer) {
    on_cancel_answered(l);
  }
}

void Rank::on_message(Arrived&& m) {
  const auto r = std::find_if(posted_.begin(), posted_.end(), [&](MPI_Request h) { return matches(operations_.at(h), m); });
  if (r == posted_.end()) {
    unexpected_.push_back(std::move(m));
    return;
  }
  const MPI_Request h = *r;
  posted_.erase(r);
  match(operations_.at(h), h, std::move(m));
}

void Rank::match(Operation& r, MPI_Request handle, Arrived&& m) {
  r.status.MPI_TAG = m.tag;
  r.status.MPI_SOURCE = rank_in(*r.members, m.source);
  r.status.gcsim_bytes = m.size;
  if (!m.rendezvous) {
    deliver(r, m.data);
    mailbox_.recycle(std::move(m.data));
    return;
  }
  mailbox_.send(m.source, envelope(kClearToSend, 0, m.context, handle, m.sender_op), {});
}

void Rank::deliver(Operation& r, std::span<const std::byte> data) {
  r.done = true;
  r.status.MPI_ERROR = MPI_SUCCESS;
  if (r.is_raw) {
    // A block of another size than this rank expects (counts or types that disagree between the
    // ranks' calls, as the v-forms allow to write): the collective's error, not the progress
    // loop's, which must go on taking the other letters of its batch.
    if (data.size() > r.raw.size()) r.status.MPI_ERROR = MPI_ERR_TRUNCATE;
    if (data.size() < r.raw.size()) r.status.MPI_ERROR = MPI_ERR_COUNT;
    std::copy_n(data.begin(), std::min(data.size(), r.raw.size()), r.raw.begin());
    return;
  }
  const MPI_Count capacity = pack_size(r.count, *r.type);
  MPI_Count position = 0;
  if (static_cast<MPI_Count>(data.size()) > capacity) {
    r.status.MPI_ERROR = MPI_ERR_TRUNCATE;
    r.status.gcsim_bytes = capacity;
    unpack(data.first(static_cast<std::size_t>(capacity)), position, r.buffer, r.count, *r.type);
    return;
  }
  const MPI_Count whole = count_of(static_cast<MPI_Count>(data.size()), *r.type);
  const MPI_Count elements = whole == MPI_UNDEFINED ? 0 : whole;
  unpack(data, position, r.buffer, elements, *r.type);
}

}  // namespace gcsim::mpi_layer
