// Sending, delivering and handing over messages on the simulated machine (MessageTransport).
#include "parix/sim/message_transport.hpp"

#include <exception>

#include "parix/sim/sim_process.hpp"
#include "parix/sim/sim_request.hpp"

namespace gcsim::parix::detail {

using machine::TraceKind;

// Inline into accept: costs the 64-node ring 1 instruction a message, saves the 4096-node one 16.
inline void MessageTransport::hold(LinkEnd& e, Message&& m) {
  // Held by the receiver's node until a receive takes it. A node out of memory here fails the
  // run as soon as this event is over (the kernel's loop stops on a failure).
  if (!m.data.empty()) {
    MemoryLedger& memory = parts_.memory;
    const auto bytes = static_cast<std::int64_t>(m.data.size());
    if (!memory.declare_message(e.owner, bytes, memory.received_kind()) && !parts_.processes.failure()) [[unlikely]] {
      parts_.processes.fail(std::make_exception_ptr(OutOfMemoryError(memory.refusal(e.owner, bytes, memory.received_kind()))));
    }
  }
  HeldMessage& held = e.arrived.append();
  held.data = std::move(m.data);
  // An asynchronous send completed on arrival: the queue keeps no hold on it, so its process can
  // reuse the request (send_request) while the message waits here.
  if (m.synchronous) held.send = std::move(m.send);
  held.synchronous = m.synchronous;
}

inline void MessageTransport::hand_over(LinkEnd& e, Message&& m) {
  if (!m.synchronous) m.send.state()->complete();
  if (e.receives.empty()) return hold(e, std::move(m));
  PostedReceive& posted = e.receives.front();
  if (SimProcess* receiver = posted.receiver) {
    posted.into->swap(m.data);  // the receiver's old storage stays in m's slot (deliver), for its next message
    if (m.data.capacity() > kSlotKeepsBytes) [[unlikely]] parts_.payloads.give(std::move(m.data));
    e.receives.drop_front();
    if (m.synchronous) m.send.state()->complete();
    return receiver->received_into(m.sent);
  }
  Request r = std::move(posted.request);
  r.state()->data = std::move(m.data);
  sim_state(r).sent_at = m.sent;
  e.receives.drop_front();
  if (m.synchronous) m.send.state()->complete();
  r.state()->complete();
}

// Inline into deliver: an untraced arrival, to a receive waiting for it or to the queue (a large
// ring's messages mostly arrive first). A withdrawn message or a trace is out of line.
[[gnu::always_inline]] inline void MessageTransport::accept(LinkEnd& e, Message&& m) {
  if (m.send.cancelled() || parts_.trace.enabled()) [[unlikely]] return accept_slow(e, std::move(m));
  hand_over(e, std::move(m));
}

void MessageTransport::accept_slow(LinkEnd& e, Message&& m) {
  // Withdrawn by its sender (SimProcess::cancel) while it travelled: the link drops it, after the
  // network and the in-order delivery have finished with it.
  if (m.send.cancelled()) {
    parts_.payloads.give(std::move(m.data));
    return;
  }
  if (parts_.trace.enabled()) {
    parts_.trace.record({TraceKind::message, m.src, e.owner, m.sent, parts_.kernel.now(),
                         static_cast<std::int64_t>(m.data.size()), m.id, "message"});
  }
  hand_over(e, std::move(m));
}

void MessageTransport::deliver(Message& m) {  // m stays put: nothing parks a message during a delivery
  if (!m.data.empty()) parts_.memory.release_in_flight(m.src, static_cast<std::int64_t>(m.data.size()));
  LinkEnd& e = *m.dst;
  if (e.order.admit(m.link_seq, m)) [[likely]] {
    accept(e, std::move(m));
    if (e.order.holds_any()) [[unlikely]] release_held(e);
  }
  // Its payload went on (to a receive, the link's queue, the held messages or the pool); the
  // request it keeps alive must not wait for the slot's reuse.
  m.send = Request();
  free_slots_.push_back(&m);
  // The last message to a closed link may free it; e's handle is its peer's peer_end.
  if (!e.open) [[unlikely]] parts_.links.release_if_done(e.peer_at->peer_end);
}

void MessageTransport::release_held(LinkEnd& e) {
  e.order.release_held([this, &e](Message&& next) {
    accept(e, std::move(next));
    parts_.payloads.give(std::move(next.data));  // not in a slot: what a receiver's vector left goes to the pool
  });
}

}  // namespace gcsim::parix::detail
