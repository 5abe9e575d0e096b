#include "machine/flow_network.hpp"

#include <algorithm>
#include <limits>

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
  const std::uint64_t id = next_id_++;
  Flow f;
  f.route = ctx_.mesh.route(src, dst);
  f.bytes = bytes;
  f.remaining = static_cast<double>(bytes);
  f.on_arrival = std::move(on_arrival);
  flows_.emplace(id, std::move(f));
  ctx_.kernel.after(lat, [this, id] { start_flow(id); });
}

void FlowNetwork::advance_to_now() {
  const SimTime now = ctx_.kernel.now();
  const double dt = to_seconds(now - last_update_);
  if (dt > 0) {
    for (auto& [id, f] : flows_) {
      if (f.transmitting) f.remaining = std::max(0.0, f.remaining - f.rate * dt);
    }
  }
  last_update_ = now;
}

void FlowNetwork::start_flow(std::uint64_t id) {
  advance_to_now();
  Flow& f = flows_.at(id);
  f.started = ctx_.kernel.now();
  f.transmitting = true;
  reshare();
}

void FlowNetwork::finish_flow(std::uint64_t id, std::uint64_t version) {
  auto it = flows_.find(id);
  if (it == flows_.end() || it->second.version != version) return;  // rescheduled since
  advance_to_now();
  Flow f = std::move(it->second);
  flows_.erase(it);
  account(f.route, f.bytes, f.started, ctx_.kernel.now());
  reshare();
  f.on_arrival();
}

// Max-min fair rates by progressive filling: repeatedly saturate the channel that offers the
// smallest equal share to the flows still unassigned, and fix those flows at that share.
void FlowNetwork::reshare() {
  const double capacity = ctx_.config.channel_bandwidth();
  std::map<int, double> left;     // channel -> bandwidth not yet assigned
  std::map<int, int> unassigned;  // channel -> transmitting flows without a rate yet
  std::vector<Flow*> todo;
  for (auto& [id, f] : flows_) {
    if (!f.transmitting) continue;
    todo.push_back(&f);
    for (int ch : f.route) {
      left.try_emplace(ch, capacity);
      ++unassigned[ch];
    }
  }
  while (!todo.empty()) {
    int bottleneck = -1;
    double share = std::numeric_limits<double>::infinity();
    for (const auto& [ch, n] : unassigned) {
      if (n > 0 && left[ch] / n < share) {
        share = left[ch] / n;
        bottleneck = ch;
      }
    }
    std::vector<Flow*> rest;
    for (Flow* f : todo) {
      if (std::find(f->route.begin(), f->route.end(), bottleneck) == f->route.end()) {
        rest.push_back(f);
        continue;
      }
      f->rate = share;
      for (int ch : f->route) {
        left[ch] -= share;
        --unassigned[ch];
      }
    }
    todo.swap(rest);
  }
  const SimTime now = ctx_.kernel.now();
  for (auto& [id, f] : flows_) {
    if (!f.transmitting) continue;
    ++f.version;
    // Same expression as NetworkModel::serialization, so a lone flow matches the analytic model.
    const SimTime eta = now + from_seconds(f.remaining / f.rate);
    ctx_.kernel.at(eta, [this, id = id, v = f.version] { finish_flow(id, v); });
  }
}

}  // namespace gcsim::machine
