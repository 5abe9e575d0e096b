#pragma once
// The simulated runtime's addressed messages (parix/mailbox.hpp): every processor's mailbox, the
// letters in the network, per ordered pair the sending order, and per unordered pair when its
// connection is up. A letter leaves when the pair's connection is up (the first letter of a pair
// asks the connection service, as connect() does), crosses the network model like any message,
// and is put in the receiver's mailbox in its pair's sending order; the receiver's await wakes.
// Between two processors of one node (SimulationOptions::processors_per_node) a letter needs no
// connection and no network: it arrives after the network model's zero-hop time, its set-up
// (NetworkModel::uncontended_time(0, n) = [network] message_setup).
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "machine/connection_service.hpp"
#include "machine/kernel.hpp"
#include "machine/network_model.hpp"
#include "machine/trace.hpp"
#include "parix/mailbox.hpp"
#include "parix/run_result.hpp"
#include "parix/activity.hpp"
#include "parix/sim/in_order_delivery.hpp"
#include "parix/sim/payload_pool.hpp"
#include "parix/sim/request_pool.hpp"

namespace gcsim::parix::detail {

class PostOffice {
 public:
  struct Parts {  // all outlive the post office
    machine::Kernel& kernel;
    machine::NetworkModel& network;
    machine::ConnectionService& connections;
    std::vector<ProcessorStats>& stats;
    const std::vector<int>& node_of;
    machine::TraceWriter& trace;  // each delivered letter is a message record, as a link's message is
    RequestPool& requests;        // a letter's request state, recycled
    PayloadPool& payloads;        // a letter's bytes, recycled when the receiver gives them back
  };
  explicit PostOffice(const Parts& parts);

  // watched: the returned request completes at delivery; else it is empty (no request is made).
  Request post(int source, int dest, const Envelope& envelope, std::span<const std::byte> data, bool watched);
  void collect(int processor, std::vector<Letter>& into);
  // A collected letter's storage, done with: kept for later letters.
  void recycle(Bytes&& storage) { parts_.payloads.give(std::move(storage)); }
  bool has_mail(int processor) const { return !boxes_[static_cast<std::size_t>(processor)].empty(); }
  // When the oldest letter in processor's box was posted (meaningful while has_mail): the sender's
  // act that ended a wait for mail, for the waiting counter.
  machine::SimTime oldest_posted(int processor) const { return oldest_posted_[static_cast<std::size_t>(processor)]; }
  // Who to wake when a letter arrives for processor (null: nobody waits).
  void set_waiter(int processor, Waiter* w) { waiters_[static_cast<std::size_t>(processor)] = w; }

 private:
  struct InTransit {
    Letter letter;
    int dest = -1;
    Request sent;  // empty for an unwatched letter
    machine::SimTime posted = 0;
    std::int64_t id = 0;
  };
  struct Ordered {  // one sender to one receiver
    std::int64_t sent = 0;
    machine::SimTime up = -1;  // when the pair's connection is up, once its first letter asked
    InOrderDelivery<InTransit> delivery;
  };
  machine::SimTime connection_up(int a, int b);
  // A letter in the network, in a slot of flying_ (slots are reused: no allocation per letter).
  struct Flying {
    std::int64_t seq = 0;
    Ordered* order = nullptr;  // its pair's (the map's entries never move)
    InTransit transit;
  };
  // An ordered pair as one hashed key: a letter's look-up is one hash, not a tree's descent.
  static std::uint64_t pair_key(int a, int b) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 | static_cast<std::uint32_t>(b);
  }
  void leave(std::uint32_t slot, int from_node, int to_node, std::int64_t bytes);
  void arrive(std::uint32_t slot);
  void deliver(InTransit&& t);

  Parts parts_;
  std::vector<std::vector<Letter>> boxes_;
  std::vector<Waiter*> waiters_;
  std::vector<machine::SimTime> oldest_posted_;  // per box, of its first letter
  std::unordered_map<std::uint64_t, machine::SimTime> up_;  // unordered pair (low, high) -> link up
  std::unordered_map<std::uint64_t, Ordered> ordered_;     // (source, dest) -> its order
  struct LastPair {  // per sender, the pair of its last letter (the map's entries never move)
    int dest = -1;
    Ordered* order = nullptr;
  };
  std::vector<LastPair> last_pair_;
  std::vector<Flying> flying_;
  std::vector<std::uint32_t> free_slots_;
  std::int64_t next_id_ = 0;
};

}  // namespace gcsim::parix::detail
