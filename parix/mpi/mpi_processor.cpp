#include "parix/mpi/mpi_processor.hpp"

#include <mpi.h>

#include <exception>
#include <thread>

#include <fmt/format.h>

namespace gcsim::parix::mpi {
namespace {

// An MPI request behind a parix Request. Receives are matched by probe when they complete, so
// the size need not be known when they are posted.
struct MpiRequest : RequestState {
  MPI_Request request = MPI_REQUEST_NULL;  // sends
  Bytes buffer;                            // a send's copy of the data, alive until it completes
  int tag = 0;
};

// A new MpiRequest, held by `handle` at once; deleted (RequestState's default) when its last
// Request lets go, so requests may outlive the processor that made them.
MpiRequest& new_request(Request& handle) {
  auto* r = new MpiRequest;
  handle = Request(r);
  return *r;
}

// One MPI tag per link: the k-th link two processors open with a parix tag gets the same MPI tag
// on both sides (connects match in call order), and MPI keeps the order of messages with one
// (source, tag): a link delivers in sending order.
int mpi_tag(int parix_tag, std::int64_t instance) {
  return static_cast<int>((instance % 32768) * 65536 + (static_cast<unsigned>(parix_tag) & 0xffffu));
}

// Polling loops yield first, then back off: ranks may share host cores (mpirun --oversubscribe).
void back_off(int spins) {
  if (spins < 1000) std::this_thread::yield();
  else std::this_thread::sleep_for(std::chrono::microseconds(50));
}

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw ParixError(fmt::format("MPI error in {}", what));
}

}  // namespace

SimTime RankState::now() const {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - epoch).count() *
         machine::kNanosecond;
}

void RankState::record(machine::TraceRecord r, std::string_view label) {
  if (!tracing) return;
  std::lock_guard<std::mutex> g(lock);
  labels.push_back(std::make_unique<std::string>(label));
  r.label = *labels.back();
  records.push_back(r);
}

MpiProcessor::~MpiProcessor() {
  drop_persistent_links();
  if (rank_.main == this) rank_.main = nullptr;
}

void MpiProcessor::compute(std::span<const OpCount> ops) {
  std::lock_guard<std::mutex> g(rank_.lock);
  for (const OpCount& op : ops) {
    if (op.count < 0) throw ParixError("compute: negative count for operation '" + std::string(op.op) + "'");
    auto it = rank_.stats.ops.find(op.op);
    if (it == rank_.stats.ops.end()) rank_.stats.ops.emplace(std::string(op.op), op.count);
    else it->second += op.count;
  }
}

void MpiProcessor::use_memory(std::int64_t bytes, std::string_view kind) {
  // The same limit as the simulated node's; MPI's own message buffers are not the model's to count.
  std::lock_guard<std::mutex> g(rank_.lock);
  if (!rank_.memory.use(bytes, kind)) throw OutOfMemoryError(rank_.memory.report(id(), bytes, kind));
}

void MpiProcessor::count_comm(SimTime start, SimTime end, int peer, std::int64_t bytes, const char* call,
                              machine::TraceKind kind) {
  {
    std::lock_guard<std::mutex> g(rank_.lock);
    rank_.stats.comm += end - start;
    if (kind == machine::TraceKind::connect) rank_.stats.connect += end - start;
  }
  if (end > start) rank_.record({kind, id(), peer, start, end, bytes, -1, {}, thread_}, call);
}

Link MpiProcessor::connect(int peer, int tag) {
  if (peer < 0 || peer >= count())
    throw ParixError(fmt::format("processor {}: connect to processor {}, which does not exist (0..{})", id(), peer, count() - 1));
  if (peer == id()) throw ParixError(fmt::format("processor {}: connect to itself; a link needs two processors", id()));
  const SimTime start = now();
  std::int64_t instance;
  {
    std::lock_guard<std::mutex> g(rank_.lock);
    instance = rank_.links_opened[{peer, tag}]++;
    ++rank_.stats.connections;
  }
  const int t = mpi_tag(tag, instance);
  // Both ends must have called connect: each sends an empty message on the link and waits for
  // the other's, which is also the first message on the link's tag.
  MPI_Request handshake;
  check(MPI_Isend(nullptr, 0, MPI_BYTE, rank_.rank_of_processor(peer), t, MPI_COMM_WORLD, &handshake), "connect");
  check(MPI_Recv(nullptr, 0, MPI_BYTE, rank_.rank_of_processor(peer), t, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "connect");
  check(MPI_Wait(&handshake, MPI_STATUS_IGNORE), "connect");
  std::int64_t handle;
  {
    std::lock_guard<std::mutex> g(rank_.lock);
    handle = rank_.next_link++;
    rank_.links.emplace(handle, MpiLink{peer, t});
  }
  count_comm(start, now(), peer, 0, "connect", machine::TraceKind::connect);
  return Link(rank_.main ? static_cast<Processor*>(rank_.main) : this, peer, tag, handle);
}

void MpiProcessor::close_link(std::int64_t handle) {
  std::lock_guard<std::mutex> g(rank_.lock);
  rank_.links.erase(handle);
}

MpiLink MpiProcessor::link_info(const Link& link, const char* call) const {
  if (!link.valid()) throw ParixError(fmt::format("processor {}: {} on a link that is not open", id(), call));
  std::lock_guard<std::mutex> g(rank_.lock);
  auto it = rank_.links.find(link.handle());
  if (it == rank_.links.end()) throw ParixError(fmt::format("processor {}: {} on a link of another processor", id(), call));
  return it->second;
}

void MpiProcessor::send(Link& link, std::span<const std::byte> data) {
  const MpiLink l = link_info(link, "send");
  const SimTime start = now();
  // Synchronous mode: returns once the receiver has started to take the message, as PARIX's send.
  check(MPI_Ssend(data.data(), static_cast<int>(data.size()), MPI_BYTE, rank_.rank_of_processor(l.peer), l.mpi_tag, MPI_COMM_WORLD), "send");
  {
    std::lock_guard<std::mutex> g(rank_.lock);
    ++rank_.stats.messages_sent;
    rank_.stats.bytes_sent += static_cast<std::int64_t>(data.size());
  }
  count_comm(start, now(), l.peer, static_cast<std::int64_t>(data.size()), "send", machine::TraceKind::send);
}

Request MpiProcessor::isend(Link& link, std::span<const std::byte> data) {
  const MpiLink l = link_info(link, "send");
  Request handle;
  MpiRequest& r = new_request(handle);
  r.peer = l.peer;
  r.link = link.handle();
  r.buffer.assign(data.begin(), data.end());
  check(MPI_Isend(r.buffer.data(), static_cast<int>(r.buffer.size()), MPI_BYTE, rank_.rank_of_processor(l.peer), l.mpi_tag, MPI_COMM_WORLD, &r.request),
        "isend");
  std::lock_guard<std::mutex> g(rank_.lock);
  ++rank_.stats.messages_sent;
  rank_.stats.bytes_sent += static_cast<std::int64_t>(data.size());
  return handle;
}

Request MpiProcessor::irecv(Link& link) {
  const MpiLink l = link_info(link, "recv");
  Request handle;
  MpiRequest& r = new_request(handle);
  r.is_receive = true;
  r.peer = l.peer;
  r.link = link.handle();
  r.tag = l.mpi_tag;
  return handle;
}

bool MpiProcessor::poll(RequestState& state) {
  if (!state.running()) return true;
  auto& r = static_cast<MpiRequest&>(state);
  if (!r.is_receive) {
    int flag = 0;
    check(MPI_Test(&r.request, &flag, MPI_STATUS_IGNORE), "wait");
    if (!flag) return false;
    r.buffer.clear();
    r.complete();
    return true;
  }
  int flag = 0;
  MPI_Message message;
  MPI_Status status;
  check(MPI_Improbe(rank_.rank_of_processor(r.peer), r.tag, MPI_COMM_WORLD, &flag, &message, &status), "recv");
  if (!flag) return false;
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  r.data.resize(static_cast<std::size_t>(size));
  check(MPI_Mrecv(r.data.data(), size, MPI_BYTE, &message, MPI_STATUS_IGNORE), "recv");
  r.complete();
  return true;
}

void MpiProcessor::block_on(RequestState& r, const char* call, machine::TraceKind kind) {
  const SimTime start = now();
  for (int spins = 0; !poll(r); ++spins) back_off(spins);
  if (r.cancelled()) return;  // withdrawn: returns at once, as on the simulated backend
  count_comm(start, now(), r.peer, static_cast<std::int64_t>(r.data.size()), call, kind);
}

Bytes MpiProcessor::recv(Link& link) {
  Request r = irecv(link);
  block_on(*r.state(), "recv", machine::TraceKind::recv);
  return r.take();
}

// No pool here: take_into frees into's old storage (MPI's own buffers dominate this backend's cost).
void MpiProcessor::recv(Link& link, Bytes& into) {
  Request r = irecv(link);
  block_on(*r.state(), "recv", machine::TraceKind::recv);
  r.take_into(into);
}

void MpiProcessor::wait(Request& r) {
  if (!r.valid()) throw ParixError(fmt::format("processor {}: wait on an empty request", id()));
  block_on(*r.state(), "wait", machine::TraceKind::wait);
}

std::size_t MpiProcessor::wait_any(std::span<Request* const> rs) {
  if (rs.empty()) throw ParixError(fmt::format("processor {}: wait_any on no requests", id()));
  const SimTime start = now();
  for (int spins = 0;; ++spins) {
    bool any_running = false;
    for (std::size_t i = 0; i < rs.size(); ++i) {
      if (!rs[i]->valid()) throw ParixError(fmt::format("processor {}: wait_any on an empty request", id()));
      if (rs[i]->cancelled()) continue;
      any_running = true;
      if (poll(*rs[i]->state())) {
        count_comm(start, now(), rs[i]->state()->peer, 0, "wait_any", machine::TraceKind::wait);
        return i;
      }
    }
    if (!any_running) throw ParixError(fmt::format("processor {}: wait_any on {} requests, all cancelled", id(), rs.size()));
    back_off(spins);
  }
}

bool MpiProcessor::cancel(Request& request) {
  if (!request.valid()) throw ParixError(fmt::format("processor {}: cancel on an empty request", id()));
  RequestState& r = *request.state();
  if (!r.running()) return r.cancelled();
  // A receive is matched (MPI_Improbe + MPI_Mrecv) only inside poll, so a running one holds no
  // message: withdrawing it is marking it, and the message it would have taken stays queued in
  // MPI for the link's next receive.
  if (r.is_receive) {
    r.cancel();
    return true;
  }
  if (poll(r)) return false;  // MPI has completed the send: it is done
  throw ParixError(fmt::format("processor {}: cancel of a send to processor {} still in progress: the MPI backend cannot "
                               "withdraw a message MPI has taken (MPI_Cancel of sends is deprecated and not honoured by Open MPI)",
                               id(), r.peer));
}

Thread MpiProcessor::spawn(std::function<void(Processor&)> body) {
  const int thread = rank_.next_thread++;
  // A thread's exception is kept for the end of the run (Thread::join runs in a destructor and
  // must not throw), as the simulated backend does.
  auto worker = std::make_shared<std::thread>([this, thread, body = std::move(body)] {
    MpiProcessor child(rank_, thread);
    try {
      body(child);
    } catch (...) {
      std::lock_guard<std::mutex> g(rank_.lock);
      if (!rank_.failure) rank_.failure = std::current_exception();
    }
  });
  return Thread([worker] { worker->join(); });
}

}  // namespace gcsim::parix::mpi
