#include "machine/flow_network.hpp"

#include <algorithm>
#include <limits>
#include <set>

namespace gcsim::machine {

void FlowNetwork::transfer(int src, int dst, std::int64_t bytes, Kernel::Action on_arrival) {
  ++messages_;
  const int hops = ctx_.mesh.hops(src, dst);
  const SimTime lat = latency(hops);
  if (hops == 0 || bytes <= 0) {
    // Nothing crosses a channel: the latency is all there is.
    ctx_.kernel.after(lat, std::move(on_arrival));
    return;
  }
  if (on_channel_.empty()) on_channel_.resize(ctx_.mesh.channel_count());
  const std::uint64_t id = next_id_++;
  Flow f;
  f.route = ctx_.mesh.route(src, dst);
  f.bytes = bytes;
  f.remaining = static_cast<double>(bytes);
  f.on_arrival = std::move(on_arrival);
  flows_.emplace(id, std::move(f));
  ctx_.kernel.after(lat, [this, id] { start_flow(id); });
}

void FlowNetwork::start_flow(std::uint64_t id) {
  Flow& f = flows_.at(id);
  f.started = f.updated = ctx_.kernel.now();
  f.transmitting = true;
  for (int ch : f.route) on_channel_[ch].push_back(id);
  reshare(f.route);
}

void FlowNetwork::finish_flow(std::uint64_t id, std::uint64_t version) {
  auto it = flows_.find(id);
  if (it == flows_.end() || it->second.version != version) return;  // rescheduled since
  Flow f = std::move(it->second);
  flows_.erase(it);
  for (int ch : f.route) {
    auto& v = on_channel_[ch];
    v.erase(std::find(v.begin(), v.end(), id));
  }
  account(f.route, f.bytes, f.started, ctx_.kernel.now());
  reshare(f.route);
  f.on_arrival();
}

void FlowNetwork::reshare(const std::vector<int>& seed) {
  // The component of flows linked through shared channels; no other flow's rate can change.
  std::set<std::uint64_t> component;
  std::set<int> channels;
  std::vector<int> frontier(seed.begin(), seed.end());
  while (!frontier.empty()) {
    const int ch = frontier.back();
    frontier.pop_back();
    if (!channels.insert(ch).second) continue;
    for (std::uint64_t id : on_channel_[ch]) {
      if (component.insert(id).second) {
        for (int c : flows_.at(id).route) {
          if (!channels.count(c)) frontier.push_back(c);
        }
      }
    }
  }
  if (component.empty()) return;

  // Max-min fair rates by progressive filling: repeatedly saturate the channel that offers the
  // smallest equal share to the flows still unassigned, and fix those flows at that share.
  const double capacity = ctx_.config.channel_bandwidth();
  std::map<int, double> left;
  std::map<int, int> unassigned;
  for (int ch : channels) {
    left[ch] = capacity;
    unassigned[ch] = static_cast<int>(on_channel_[ch].size());
  }
  std::map<std::uint64_t, double> rate;
  std::vector<std::uint64_t> todo(component.begin(), component.end());
  while (!todo.empty()) {
    int bottleneck = -1;
    double share = std::numeric_limits<double>::infinity();
    for (const auto& [ch, n] : unassigned) {
      if (n > 0 && left[ch] / n < share) {
        share = left[ch] / n;
        bottleneck = ch;
      }
    }
    std::vector<std::uint64_t> rest;
    for (std::uint64_t id : todo) {
      const Flow& f = flows_.at(id);
      if (std::find(f.route.begin(), f.route.end(), bottleneck) == f.route.end()) {
        rest.push_back(id);
        continue;
      }
      rate[id] = share;
      for (int ch : f.route) {
        left[ch] -= share;
        --unassigned[ch];
      }
    }
    todo.swap(rest);
  }

  const SimTime now = ctx_.kernel.now();
  for (auto [id, r] : rate) {
    Flow& f = flows_.at(id);
    if (f.version != 0 && r == f.rate) continue;  // unchanged: its completion event still holds
    f.remaining = std::max(0.0, f.remaining - f.rate * to_seconds(now - f.updated));
    f.updated = now;
    f.rate = r;
    ++f.version;
    // Same expression as NetworkModel::serialization, so a lone flow matches the analytic model.
    const SimTime eta = now + from_seconds(f.remaining / f.rate);
    ctx_.kernel.at(eta, [this, id = id, v = f.version] { finish_flow(id, v); });
  }
}

}  // namespace gcsim::machine
