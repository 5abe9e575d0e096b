#pragma once
// One end of a virtual link on the simulated machine: its owner and peer, the messages the peer
// sent that arrived out of order or before a receive, and the receives waiting for one.
#include <cstdint>

#include "machine/ring_buffer.hpp"
#include "parix/sim/in_order_delivery.hpp"
#include "parix/sim/message.hpp"

namespace gcsim::parix::detail {

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

}  // namespace gcsim::parix::detail
