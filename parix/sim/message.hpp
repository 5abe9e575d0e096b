#pragma once
// A message of the simulated runtime in its three forms: travelling (Message, in a slot that never
// moves), arrived before its receive (HeldMessage, in its link end's queue), and the receive that
// waits for one (PostedReceive).
#include <cstdint>

#include "machine/sim_time.hpp"
#include "parix/processor.hpp"

namespace gcsim::parix::detail {

struct LinkEnd;
class SimProcess;

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

// A receive waiting on its link end: a request, or a blocking receive into the caller's vector
// (untraced, no [comm_cpu] charge: nothing asks a request's size), which needs none. Its message is
// swapped straight into that vector and its process woken (MessageTransport::hand_over); the
// caller's old storage stays with the message's slot for the next message sent in it.
struct PostedReceive {
  Request request;                 // null for a receive into a vector
  Bytes* into = nullptr;           // the vector, or null
  SimProcess* receiver = nullptr;  // whom to wake, or null
};

}  // namespace gcsim::parix::detail
