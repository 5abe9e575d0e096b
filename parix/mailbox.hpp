#pragma once
// Addressed messages, the runtime extension an MPI layer needs: a processor sends a letter to any
// processor by its id, with no connect() by either end, and each processor takes what arrived from
// its mailbox. Semantics (simulated backend):
//  - post() returns at once; its request completes when the letter is in the receiver's mailbox.
//  - Letters from one sender to one receiver arrive in sending order (the network may let a short
//    one overtake a long one; the mailbox holds it back, as a link does).
//  - The first letter between a pair of processors, in either direction, waits for the connection
//    set-up of the machine file's connection model, as connect() pays it; later letters do not.
//  - The envelope is the layer's own (kind, communicator context, tag, ...): the runtime carries it
//    and never reads it, so matching by source, tag and context is the layer's.
//  - await() blocks until a letter arrives that collect() has not taken, or one of the given
//    requests is over; its `call` names the wait in a deadlock report, its text built only when
//    a report is written (a layer that blocks on every call need not format one each time).
// A backend whose processors are not Mailboxes (the real-MPI backend) has no addressed messages:
// mailbox_of() is then null and the layer says so.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "parix/processor.hpp"

namespace gcsim::parix {

struct Envelope {
  std::array<std::int64_t, 4> words{};
};

struct Letter {
  int source = -1;  // the sending processor
  Envelope envelope;
  Bytes data;
};

// What a blocked await() names in a deadlock report ("MPI_Recv(source=1, tag=0, ...)"); text() is
// called only for a report, while the wait still blocks.
class WaitDescription {
 public:
  virtual std::string text() const = 0;

 protected:
  ~WaitDescription() = default;
};

class Mailbox {
 public:
  virtual Request post(int dest, const Envelope& envelope, std::span<const std::byte> data) = 0;
  // post() for a letter whose delivery nobody waits for (an eager message): no request to make.
  virtual void send(int dest, const Envelope& envelope, std::span<const std::byte> data) { post(dest, envelope, data); }
  // Appends every letter that arrived since the last call to into, in arrival order.
  virtual void collect(std::vector<Letter>& into) = 0;
  // A collected letter's data, read: its storage goes back for later letters (or is freed).
  virtual void recycle(Bytes&& storage) { Bytes().swap(storage); }
  // call must stay valid while blocked; peer: the processor waited for, -1 if none in particular.
  virtual void await(std::span<const Request> requests, const WaitDescription& call, int peer) = 0;
  // The same with a fixed text, which must stay valid while blocked.
  void await(std::span<const Request> requests, const char* call, int peer) {
    const struct Fixed final : WaitDescription {
      const char* call;
      explicit Fixed(const char* c) : call(c) {}
      std::string text() const override { return call; }
    } fixed(call);
    await(requests, fixed, peer);
  }
  // Holds one of the node's CPUs for `duration`, counted as communication (as_comm) or compute.
  virtual void occupy(SimTime duration, std::string_view label, bool as_comm) = 0;
  // Puts [start, now) on this processor's track of the trace, when one is written, as a wait the
  // layer above names: `label` its call, `peer` the processor waited for (-1: none in particular),
  // `bytes` what the call moves. Only for time spent in await(), so no two intervals overlap.
  virtual void trace_blocked(std::string_view label, SimTime start, int peer, std::int64_t bytes) = 0;
  // The node processor `processor` runs on: several processors share one when a run packs them
  // (SimulationOptions::processors_per_node), and their letters then need no network.
  virtual int node_of(int processor) const = 0;

 protected:
  ~Mailbox() = default;
};

inline Mailbox* mailbox_of(Processor& p) { return dynamic_cast<Mailbox*>(&p); }

}  // namespace gcsim::parix
