#include "parix/sim/post_office.hpp"

#include <algorithm>

namespace gcsim::parix::detail {

PostOffice::PostOffice(const Parts& parts)
    : parts_(parts), boxes_(parts.stats.size()), waiters_(parts.stats.size(), nullptr) {}

machine::SimTime PostOffice::connection_up(int a, int b) {
  const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
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

Request PostOffice::post(int source, int dest, const Envelope& envelope, std::span<const std::byte> data) {
  Request sent(new RequestState);
  sent.state()->peer = dest;
  const std::int64_t id = next_id_++;
  Ordered& order = ordered_[{source, dest}];
  InTransit t{Letter{source, envelope, Bytes(data.begin(), data.end())}, sent, parts_.kernel.now(), id};
  in_flight_.emplace(id, std::pair{order.sent++, std::move(t)});
  const auto bytes = static_cast<std::int64_t>(data.size());
  parts_.stats[source].messages_sent += 1;
  parts_.stats[source].bytes_sent += bytes;
  const int from = parts_.node_of[source];
  const int to = parts_.node_of[dest];
  const machine::SimTime up = connection_up(source, dest);
  if (source == dest) {
    parts_.kernel.at(parts_.kernel.now(), [this, id] { arrive(id, in_flight_.at(id).first); });
  } else if (from == to) {  // another processor of the node: no network, the models' zero-hop time
    parts_.kernel.at(parts_.kernel.now() + parts_.network.uncontended_time(0, bytes),
                     [this, id] { arrive(id, in_flight_.at(id).first); });
  } else if (up > parts_.kernel.now()) {
    parts_.kernel.at(up, [this, id, from, to, bytes] { leave(id, from, to, bytes); });
  } else {
    leave(id, from, to, bytes);
  }
  return sent;
}

void PostOffice::leave(std::int64_t id, int from_node, int to_node, std::int64_t bytes) {
  parts_.network.transfer(from_node, to_node, bytes, [this, id] { arrive(id, in_flight_.at(id).first); });
}

void PostOffice::arrive(std::int64_t id, std::int64_t seq) {
  auto node = in_flight_.extract(id);
  InTransit t = std::move(node.mapped().second);
  Ordered& order = ordered_[{t.letter.source, static_cast<int>(t.sent.state()->peer)}];
  order.delivery.arrive(seq, std::move(t), [this](InTransit&& m) { deliver(std::move(m)); });
}

void PostOffice::deliver(InTransit&& t) {
  const auto dest = static_cast<std::size_t>(t.sent.state()->peer);
  if (parts_.trace.enabled()) {
    parts_.trace.record({machine::TraceKind::message, t.letter.source, static_cast<int>(dest), t.posted, parts_.kernel.now(),
                         static_cast<std::int64_t>(t.letter.data.size()), t.id, "message"});
  }
  boxes_[dest].push_back(std::move(t.letter));
  t.sent.state()->complete();
  if (Waiter* w = waiters_[dest]) w->wake();
}

void PostOffice::collect(int processor, std::vector<Letter>& into) {
  auto& box = boxes_[static_cast<std::size_t>(processor)];
  for (Letter& l : box) into.push_back(std::move(l));
  box.clear();
}

}  // namespace gcsim::parix::detail
