#include "parix/sim/post_office.hpp"

#include <algorithm>

namespace gcsim::parix::detail {

PostOffice::PostOffice(const Parts& parts)
    : parts_(parts),
      boxes_(parts.stats.size()),
      waiters_(parts.stats.size(), nullptr),
      oldest_posted_(parts.stats.size(), 0),
      last_pair_(parts.stats.size()) {}

machine::SimTime PostOffice::connection_up(int a, int b) {
  const std::uint64_t key = pair_key(std::min(a, b), std::max(a, b));
  const auto it = up_.find(key);
  if (it != up_.end()) return it->second;
  const machine::SimTime now = parts_.kernel.now();
  const bool one_node = parts_.node_of[a] == parts_.node_of[b];  // itself, or a processor sharing its node
  const machine::SimTime up = one_node ? now : parts_.connections.set_up(parts_.node_of[a], parts_.node_of[b], now);
  up_.emplace(key, up);
  if (!one_node) {
    parts_.stats[a].connections += 1;
    parts_.stats[b].connections += 1;
  }
  return up;
}

Request PostOffice::post(int source, int dest, const Envelope& envelope, std::span<const std::byte> data, bool watched) {
  Request sent;
  if (watched) {
    sent = parts_.requests.take();
    sent.state()->peer = dest;
  }
  const std::int64_t id = next_id_++;
  LastPair& last = last_pair_[static_cast<std::size_t>(source)];
  if (last.dest != dest) last = {dest, &ordered_[pair_key(source, dest)]};  // a sender mostly writes to one
  Ordered& order = *last.order;
  std::uint32_t slot = 0;
  if (free_slots_.empty()) {
    slot = static_cast<std::uint32_t>(flying_.size());
    flying_.emplace_back();
  } else {
    slot = free_slots_.back();
    free_slots_.pop_back();
  }
  Flying& f = flying_[slot];
  f.seq = order.sent++;
  f.order = &order;
  f.transit.letter.source = source;
  f.transit.dest = dest;
  f.transit.letter.envelope = envelope;
  parts_.payloads.copy_into(f.transit.letter.data, data);
  f.transit.sent = sent;
  f.transit.posted = parts_.kernel.now();
  f.transit.id = id;
  const auto bytes = static_cast<std::int64_t>(data.size());
  parts_.stats[source].messages_sent += 1;
  parts_.stats[source].bytes_sent += bytes;
  const int from = parts_.node_of[source];
  const int to = parts_.node_of[dest];
  if (order.up < 0) order.up = connection_up(source, dest);  // fixed once asked: no look-up per letter
  const machine::SimTime up = order.up;
  if (source == dest) {
    parts_.kernel.at(parts_.kernel.now(), [this, slot] { arrive(slot); });
  } else if (from == to) {  // another processor of the node: no network, the models' zero-hop time
    parts_.kernel.at(parts_.kernel.now() + parts_.network.uncontended_time(0, bytes), [this, slot] { arrive(slot); });
  } else if (up > parts_.kernel.now()) {
    parts_.kernel.at(up, [this, slot, from, to, bytes] { leave(slot, from, to, bytes); });
  } else {
    leave(slot, from, to, bytes);
  }
  return sent;
}

void PostOffice::leave(std::uint32_t slot, int from_node, int to_node, std::int64_t bytes) {
  parts_.network.transfer(from_node, to_node, bytes, [this, slot] { arrive(slot); });
}

void PostOffice::arrive(std::uint32_t slot) {
  Flying& f = flying_[slot];
  const std::int64_t seq = f.seq;
  Ordered& order = *f.order;
  InTransit t = std::move(f.transit);
  f.transit.letter.data = {};  // moved from: left empty for the next letter's copy
  f.transit.sent = {};
  free_slots_.push_back(slot);
  order.delivery.arrive(seq, std::move(t), [this](InTransit&& m) { deliver(std::move(m)); });
}

void PostOffice::deliver(InTransit&& t) {
  const auto dest = static_cast<std::size_t>(t.dest);
  if (parts_.trace.enabled()) {
    parts_.trace.record({machine::TraceKind::message, t.letter.source, static_cast<int>(dest), t.posted, parts_.kernel.now(),
                         static_cast<std::int64_t>(t.letter.data.size()), t.id, "message"});
  }
  if (boxes_[dest].empty()) oldest_posted_[dest] = t.posted;
  boxes_[dest].push_back(std::move(t.letter));
  if (t.sent.valid()) t.sent.state()->complete();
  if (Waiter* w = waiters_[dest]) w->wake();
}

void PostOffice::collect(int processor, std::vector<Letter>& into) {
  auto& box = boxes_[static_cast<std::size_t>(processor)];
  if (into.empty()) {  // the usual case: the two vectors trade storage, no letter moves
    into.swap(box);
    return;
  }
  for (Letter& l : box) into.push_back(std::move(l));
  box.clear();
}

}  // namespace gcsim::parix::detail
