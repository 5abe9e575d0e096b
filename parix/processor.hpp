#pragma once
// The PARIX-like API seen by an application: one Processor per virtual processor, SPMD.
//
// Semantics (identical on every backend):
//  - connect(peer, tag) opens a virtual link. Both ends must call it (with each other's id and
//    the same tag); it returns when the link is up. Opening costs the configured connection time,
//    which grows with the number of mesh hops between the two nodes. Links close when destroyed.
//  - send() is synchronous: it returns once the receiver has the message. isend() returns at once;
//    the message travels while the sender goes on. Messages on one link arrive in order.
//  - recv() blocks until a message arrives on the link; irecv()/wait()/wait_any() split that up.
//  - cancel(request) withdraws an isend or irecv that has not taken effect yet (see Processor).
//  - compute() charges simulated CPU time for counted operations (cycles per operation and clock
//    rate come from the machine file), so that simulated time is deterministic.
//  - spawn() starts a thread on the same node; it shares the node's CPUs and this processor's id.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>
#include <cstring>
#include <utility>

#include "machine/sim_time.hpp"
#include "parix/activity.hpp"

namespace gcsim::parix {

using machine::SimTime;
using Bytes = std::vector<std::byte>;

// A number of named operations, charged as cycles_per_op[op] * count / clock.
struct OpCount {
  std::string_view op;
  std::int64_t count;
};

class Processor;

// One end of a virtual link. Move-only; closes the link when destroyed.
class Link {
 public:
  Link() = default;
  // hint: backend-private, where the backend keeps this end (checked on use, never trusted).
  Link(Processor* owner, int peer, int tag, std::int64_t handle, const void* hint = nullptr)
      : owner_(owner), peer_(peer), tag_(tag), handle_(handle), hint_(hint) {}
  Link(Link&& o) noexcept { *this = std::move(o); }
  Link& operator=(Link&& o) noexcept;
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;
  ~Link();

  int peer() const { return peer_; }
  int tag() const { return tag_; }
  std::int64_t handle() const { return handle_; }  // -1 for an empty or moved-from link
  const void* hint() const { return hint_; }      // null for an empty or moved-from link
  bool valid() const { return owner_ != nullptr; }

 private:
  Processor* owner_ = nullptr;
  int peer_ = -1;
  int tag_ = 0;
  std::int64_t handle_ = -1;
  const void* hint_ = nullptr;
};

// Shared state of an asynchronous send or receive, an activity (parix/activity.hpp): running, then
// done or cancelled. Backends fill it in; its waiter is backend-private (who to wake). A backend
// keeps what else it needs in a class of its own derived from it (the simulated one:
// parix/sim/sim_request.hpp), and says there where a state goes when its last Request lets go.
// Reference-counted by the Requests that hold it (intrusively: no control block, no atomics --
// a request belongs to one host thread, the simulation's or an MPI processor's).
struct RequestState : detail::Activity {
  RequestState() = default;
  RequestState(const RequestState&) = delete;
  RequestState& operator=(const RequestState&) = delete;
  virtual ~RequestState() = default;

  bool is_receive = false;
  Bytes data;                  // received bytes once done (receives only)
  std::int64_t link = -1;      // link handle
  int peer = -1;

 private:
  friend class Request;
  // The last Request let go: deleted, unless the backend takes its states back (a pool).
  virtual void release() noexcept { delete this; }
  // The caller's old storage after Request::take_into: freed, unless the backend keeps it for
  // later messages.
  virtual void recycle(Bytes&& storage) noexcept { Bytes().swap(storage); }
  std::uint32_t refs_ = 0;
};

// Handle to an asynchronous send or receive; copies share the state.
class Request {
 public:
  Request() = default;
  // Holds s (made with new, or by a backend's home), which lives while any Request holds it.
  explicit Request(RequestState* s) noexcept : state_(s) {
    if (s) ++s->refs_;
  }
  Request(const Request& o) noexcept : Request(o.state_) {}
  Request(Request&& o) noexcept : state_(std::exchange(o.state_, nullptr)) {}
  Request& operator=(const Request& o) noexcept {
    Request(o).swap(*this);
    return *this;
  }
  Request& operator=(Request&& o) noexcept {
    Request(std::move(o)).swap(*this);
    return *this;
  }
  ~Request() {
    if (state_ && --state_->refs_ == 0) state_->release();
  }
  void swap(Request& o) noexcept { std::swap(state_, o.state_); }

  bool valid() const { return state_ != nullptr; }
  // Whether the communication completed (never true for a cancelled one); does not block.
  bool test() const { return state_ && state_->test(); }
  bool done() const { return test(); }
  // Whether Processor::cancel withdrew it.
  bool cancelled() const { return state_ && state_->cancelled(); }
  // The received bytes (a completed receive); moves them out. Empty for a cancelled receive.
  Bytes take() { return std::move(state_->data); }
  // The same into a caller-owned vector, by swapping storage: into's old contents are dropped and
  // its storage goes back to the backend for later messages (parix/sim/payload_pool.hpp), so a loop
  // that reuses one Bytes receives without allocating. into is left empty for a cancelled receive.
  void take_into(Bytes& into) {
    into.swap(state_->data);
    state_->recycle(std::move(state_->data));
  }
  RequestState* state() const { return state_; }
  // Whether this is the only Request holding its state (a backend may then reuse the state).
  bool unique() const { return state_ && state_->refs_ == 1; }

 private:
  RequestState* state_ = nullptr;
};

// A node-local thread started by Processor::spawn.
class Thread {
 public:
  Thread() = default;
  explicit Thread(std::function<void()> join) : join_(std::move(join)) {}
  Thread(Thread&&) = default;
  Thread& operator=(Thread&&) = default;
  void join() {
    if (join_) std::exchange(join_, nullptr)();
  }
  ~Thread() { join(); }

 private:
  std::function<void()> join_;
};

// Thrown into the application when the machine runs out of a resource (memory) or an API
// call is misused (connecting to oneself, an unknown operation name).
class ParixError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A node's memory would be exceeded: what() names the processor, what its node holds by kind and
// the node's memory.
class OutOfMemoryError : public ParixError {
 public:
  using ParixError::ParixError;
};

class MemoryReservation;

class Processor {
 public:
  virtual ~Processor() = default;

  virtual int id() const = 0;
  virtual int count() const = 0;
  virtual SimTime now() const = 0;
  double now_seconds() const { return machine::to_seconds(now()); }

  virtual void compute(std::span<const OpCount> ops) = 0;
  void compute(std::initializer_list<OpCount> ops) { compute(std::span(ops.begin(), ops.size())); }
  void compute(std::string_view op, std::int64_t count) { compute({OpCount{op, count}}); }
  // Work the communication layer does on the node's CPU, such as merging the parts an exchange
  // received inside the exchange routine: charged as compute() charges, counted as communication
  // (where the thesis's timers put it). The MPI backend counts the operations, as compute() does.
  virtual void compute_in_comm(std::span<const OpCount> ops) = 0;
  void compute_in_comm(std::string_view op, std::int64_t count) {
    const OpCount one{op, count};
    compute_in_comm(std::span(&one, 1));
  }

  // Declares memory of a kind ("scene", "hemicube", ...) the application holds on this node,
  // before the host allocates it (bytes may be negative to release). Throws OutOfMemoryError when
  // the node's memory would be exceeded (unless the run only warns, see SimulationOptions).
  virtual void use_memory(std::int64_t bytes, std::string_view kind) = 0;
  // The same, held until the returned reservation is destroyed:
  //   auto held = p.reserve_memory(bytes, "hemicube");  std::vector<float> buffer(...);
  [[nodiscard]] MemoryReservation reserve_memory(std::int64_t bytes, std::string_view kind);

  virtual Link connect(int peer, int tag = 0) = 0;
  virtual void send(Link& link, std::span<const std::byte> data) = 0;
  virtual Bytes recv(Link& link) = 0;
  // recv into a caller-owned vector (see Request::take_into): the allocation-free form for loops.
  virtual void recv(Link& link, Bytes& into) = 0;
  virtual Request isend(Link& link, std::span<const std::byte> data) = 0;
  virtual Request irecv(Link& link) = 0;
  virtual void wait(Request& r) = 0;
  // Blocks until one of the requests is done; returns its index (the lowest, if several are).
  // Cancelled requests are skipped; throws ParixError if every request is cancelled.
  virtual std::size_t wait_any(std::span<Request* const> rs) = 0;
  // Withdraws a communication that has not taken effect, like MPI_Cancel. Returns true if the
  // request is now cancelled (also when it already was), false if it completed first.
  //  - A receive not yet matched with a message is withdrawn: the link's next message goes to the
  //    next receive posted on it, or waits for one. A receive holding its message is done.
  //  - A send (isend) whose message has not been delivered is withdrawn: the receiver never gets
  //    it. On the simulated machine a message leaves while isend returns, so a withdrawn one still
  //    crosses the network (its time and its share of the channels are unchanged: the network
  //    model and the link's in-order delivery always finish what they started; later messages on
  //    the link arrive exactly when they would have without the cancel) and the receiving link
  //    drops it on arrival, before it is charged to the receiver's memory. A delivered send is done.
  //  - A cancelled request is finished but not done: wait() on it returns at once, taking no
  //    time; test() stays false and take() gives nothing.
  //  - MPI backend: receives as above (a receive is matched only while it is waited for). A send
  //    MPI has completed returns false; a send still in progress cannot be withdrawn safely
  //    (MPI_Cancel of sends is deprecated and not honoured by Open MPI) and throws ParixError.
  virtual bool cancel(Request& r) = 0;

  virtual Thread spawn(std::function<void(Processor&)> body) = 0;

  // A link kept open for reuse with this peer and tag, opened (both ends call it) on first use.
  Link& persistent_link(int peer, int tag = 0) {
    auto it = persistent_.find({peer, tag});
    if (it == persistent_.end()) it = persistent_.emplace(std::pair{peer, tag}, connect(peer, tag)).first;
    return it->second;
  }
  // Closes the persistent links; backends call it before a processor goes away.
  void drop_persistent_links() { persistent_.clear(); }

  // Typed helpers for trivially copyable values and vectors of them.
  template <class T>
  void send_value(Link& l, const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    send(l, std::as_bytes(std::span(&v, 1)));
  }
  template <class T>
  T recv_value(Link& l) {
    static_assert(std::is_trivially_copyable_v<T>);
    recv(l, scratch_);
    if (scratch_.size() != sizeof(T)) throw ParixError("recv_value: message size does not match the type");
    T v;
    std::memcpy(&v, scratch_.data(), sizeof(T));
    return v;
  }
  template <class T>
  void send_vector(Link& l, std::span<const T> v) {
    static_assert(std::is_trivially_copyable_v<T>);
    send(l, std::as_bytes(v));
  }
  template <class T>
  std::vector<T> recv_vector(Link& l) {
    static_assert(std::is_trivially_copyable_v<T>);
    Bytes b = recv(l);
    if (b.size() % sizeof(T) != 0) throw ParixError("recv_vector: message size is not a multiple of the element size");
    std::vector<T> v(b.size() / sizeof(T));
    if (!b.empty()) std::memcpy(v.data(), b.data(), b.size());
    return v;
  }

 protected:
  friend class Link;
  virtual void close_link(std::int64_t handle) = 0;

 private:
  std::map<std::pair<int, int>, Link> persistent_;
  Bytes scratch_;  // recv_value receives into it (one small value), so it allocates nothing per message
};

// Memory declared on this processor's node, released when destroyed. Move-only.
class MemoryReservation {
 public:
  MemoryReservation() = default;
  MemoryReservation(Processor& p, std::int64_t bytes, std::string_view kind) : kind_(kind) {
    p.use_memory(bytes, kind);  // throws before anything is held
    owner_ = &p;
    bytes_ = bytes;
  }
  MemoryReservation(MemoryReservation&& o) noexcept { *this = std::move(o); }
  MemoryReservation& operator=(MemoryReservation&& o) noexcept {
    if (this != &o) {
      release();
      owner_ = std::exchange(o.owner_, nullptr);
      bytes_ = std::exchange(o.bytes_, 0);
      kind_ = std::move(o.kind_);
    }
    return *this;
  }
  MemoryReservation(const MemoryReservation&) = delete;
  MemoryReservation& operator=(const MemoryReservation&) = delete;
  ~MemoryReservation() { release(); }

  std::int64_t bytes() const { return bytes_; }
  // Gives the memory back now.
  void release() noexcept {
    if (owner_) std::exchange(owner_, nullptr)->use_memory(-bytes_, kind_);  // releasing never throws
  }

 private:
  Processor* owner_ = nullptr;
  std::int64_t bytes_ = 0;
  std::string kind_;
};

inline MemoryReservation Processor::reserve_memory(std::int64_t bytes, std::string_view kind) {
  return MemoryReservation(*this, bytes, kind);
}

inline Link& Link::operator=(Link&& o) noexcept {
  if (this != &o) {
    if (owner_) owner_->close_link(handle_);
    owner_ = std::exchange(o.owner_, nullptr);
    peer_ = o.peer_;
    tag_ = o.tag_;
    // o names no end any more: a backend finds nothing by its handle and hint (no valid() test).
    handle_ = std::exchange(o.handle_, -1);
    hint_ = std::exchange(o.hint_, nullptr);
  }
  return *this;
}
inline Link::~Link() {
  if (owner_) owner_->close_link(handle_);
}

}  // namespace gcsim::parix
