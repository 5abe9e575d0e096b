#pragma once
// Message transport of the simulated runtime: a send copies the bytes into a Message in a slot
// that never moves and hands the network model an arrival event naming the slot; the arrival is
// delivered in its link's sending order, then handed over to the first waiting receive or held in
// the link end's queue until one comes. The runtime's copy is charged to the sender's node while
// in flight and to the receiver's until received (MemoryLedger).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "machine/kernel.hpp"
#include "machine/network_model.hpp"
#include "machine/trace.hpp"
#include "parix/sim/link_end.hpp"
#include "parix/sim/link_table.hpp"
#include "parix/sim/memory_ledger.hpp"
#include "parix/sim/payload_pool.hpp"
#include "parix/sim/process_lifetime.hpp"
#include "parix/sim/stable_vector.hpp"

namespace gcsim::parix::detail {

class MessageTransport {
 public:
  struct Parts {  // the parts of the run the transport uses, all outliving it
    machine::Kernel& kernel;
    machine::NetworkModel& network;
    machine::TraceWriter& trace;
    MemoryLedger& memory;
    PayloadPool& payloads;
    LinkTable<LinkEnd>& links;
    ProcessLifetime& processes;  // where an arrival's failure goes
  };
  explicit MessageTransport(const Parts& parts) : parts_(parts) {}

  // Sends a copy of data from processor `sender` (on node from_node) over e to its peer (on node
  // to_node); send completes when it is delivered (asynchronous) or received (synchronous). The
  // copy is declared in flight on the sender's node first: throws OutOfMemoryError if refused.
  [[gnu::always_inline]] inline void send(LinkEnd& e, int sender, int from_node, int to_node,
                                          std::span<const std::byte> data, const Request& send, bool synchronous);

  // A blocking receive by processor `receiver` that finds e's front message there: what the
  // receive's request would do with it, without the request (SimProcess::post_receive, then
  // Request::take_into). into's old storage goes back to the pool.
  void take_held(LinkEnd& e, int receiver, Bytes& into) {
    HeldMessage& m = e.arrived.front();
    if (!m.data.empty()) parts_.memory.release(receiver, static_cast<std::int64_t>(m.data.size()), parts_.memory.received_kind());
    into.swap(m.data);
    if (m.synchronous) m.send.state()->complete();
    m.send = Request();
    e.arrived.drop_front();
    parts_.payloads.give(std::move(m.data));  // leaves the slot's payload empty
  }

  // The most storage a message's slot keeps from a receiver's old vector (see PostedReceive);
  // more goes back to the pool, which bounds what it keeps.
  static constexpr std::size_t kSlotKeepsBytes = 4096;

 private:
  // The message in slot m arrived: delivered in place (no copy of it), then the slot is free.
  void deliver(Message& m);
  // Messages in the network wait in slots that never move, so callbacks can refer to them by
  // address. A free slot for the next one, which the caller fills in place: its request is null
  // (moved on or reset by deliver), its payload empty or a receiver's old storage (hand_over), to
  // be overwritten.
  Message& take_slot() {
    if (free_slots_.empty()) [[unlikely]] return in_flight_.emplace_back();
    Message& m = *free_slots_.back();
    free_slots_.pop_back();
    return m;
  }
  // A message delivered in order to its link end: to a waiting receive, else to the end's queue.
  [[gnu::always_inline]] inline void accept(LinkEnd& e, Message&& m);
  [[gnu::noinline]] void accept_slow(LinkEnd& e, Message&& m);  // withdrawn or traced
  // Accepts e's held messages that are now in order (one arrived that they had overtaken). Out of
  // line: most links never hold any.
  [[gnu::noinline]] void release_held(LinkEnd& e);
  // Completes an asynchronous send, then gives m to e's first waiting receive, or holds it.
  [[gnu::always_inline]] inline void hand_over(LinkEnd& e, Message&& m);
  // Queues m at e until a receive takes it (its send, if asynchronous, completed already).
  [[gnu::always_inline]] inline void hold(LinkEnd& e, Message&& m);

  Parts parts_;
  StableVector<Message> in_flight_;  // slots of the messages in flight, at most the run's peak
  std::vector<Message*> free_slots_;
  std::int64_t next_message_ = 0;
};

// In line into SimProcess::isend and send, as the rest of the sender's path: one call per message less.
inline void MessageTransport::send(LinkEnd& e, int sender, int from_node, int to_node, std::span<const std::byte> data,
                                   const Request& send, bool synchronous) {
  // The runtime's copy of the message is held by the sender's node until it is delivered, then
  // by the receiver's until received; declared before the host allocates it.
  const std::int64_t bytes = static_cast<std::int64_t>(data.size());
  MemoryLedger& memory = parts_.memory;
  if (bytes > 0) {
    if (!memory.declare_message(sender, bytes, memory.in_flight_kind())) {
      throw OutOfMemoryError(memory.refusal(sender, bytes, memory.in_flight_kind()));
    }
  }
  // Built in its slot; the arrival callback captures only (transport, slot), small enough for
  // the kernel to store inline, which keeps the per-message cost free of extra allocations.
  Message& m = take_slot();
  parts_.payloads.copy_into(m.data, data);
  m.send = send;
  m.synchronous = synchronous;
  m.id = next_message_++;
  m.link_seq = e.sent++;
  m.src = sender;
  m.sent = parts_.kernel.now();
  m.dst = e.peer_at;
  parts_.network.transfer(from_node, to_node, bytes, [transport = this, &m] { transport->deliver(m); });
}

}  // namespace gcsim::parix::detail
