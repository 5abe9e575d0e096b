#include "machine/flow_network.hpp"

#include <algorithm>

namespace gcsim::machine {

void FlowNetwork::transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  ++messages_;
  const int hops = ctx_.mesh.hops(src, dst);
  const SimTime lat = latency(hops);
  if (hops == 0 || bytes <= 0) {
    // Nothing crosses a channel: the latency is all there is.
    ctx_.kernel.after(lat, std::move(on_arrival));
    return;
  }
  if (on_channel_.empty()) {
    const auto channels = static_cast<std::size_t>(ctx_.mesh.channel_count());
    on_channel_.resize(channels);
    channel_visited_.assign(channels, 0);
    left_.assign(channels, 0.0);
    unassigned_.assign(channels, 0);
  }
  const std::uint64_t id = next_id_++;
  Flow& f = new_flow(id);
  f.id = id;
  ctx_.mesh.route(src, dst, f.route);
  f.bytes = bytes;
  f.remaining = static_cast<double>(bytes);
  f.on_arrival = std::move(on_arrival);
  ctx_.kernel.after(lat, [this, id] { start_flow(id); });
}

void FlowNetwork::start_flow(std::uint64_t id) {
  Flow& f = flows_.at(id);
  f.started = f.updated = ctx_.kernel.now();
  f.transmitting = true;
  for (int ch : f.route) on_channel_[ch].push_back(&f);
  reshare(f.route);
}

void FlowNetwork::finish_flow(std::uint64_t id, std::uint64_t version) {
  auto it = flows_.find(id);
  if (it == flows_.end() || it->second.version != version) return;  // rescheduled since
  Flow& f = it->second;
  for (int ch : f.route) {
    auto& v = on_channel_[ch];
    v.erase(std::find(v.begin(), v.end(), &f));
  }
  account(f.route, f.bytes, f.started, ctx_.kernel.now());
  reshare(f.route);
  Kernel::Action on_arrival = std::move(f.on_arrival);
  spare_flows_.push_back(flows_.extract(it));
  on_arrival();
}

FlowNetwork::Flow& FlowNetwork::new_flow(std::uint64_t id) {
  // Ids only grow, so a new flow goes at the end (the hint makes the insertion constant time).
  if (spare_flows_.empty()) return flows_.emplace_hint(flows_.end(), id, Flow{})->second;
  Flows::node_type node = std::move(spare_flows_.back());
  spare_flows_.pop_back();
  std::vector<int> route = std::move(node.mapped().route);
  node.mapped() = Flow{};
  node.mapped().route = std::move(route);
  node.key() = id;
  return flows_.insert(flows_.end(), std::move(node))->second;
}

// The component of flows linked through shared channels; no other flow's rate can change.
void FlowNetwork::collect_component(const std::vector<int>& seed) {
  ++solve_;
  component_channels_.clear();
  component_flows_.clear();
  // A channel is marked when it is first queued, so that each is queued once however many of the
  // component's flows cross it (about 37 channels per route at 4096 nodes). The order of the visit
  // changes no rate: the filling breaks ties by channel number and reschedules in flow order.
  frontier_.clear();
  auto enqueue = [&](int ch) {
    if (channel_visited_[ch] == solve_) return;
    channel_visited_[ch] = solve_;
    frontier_.push_back(ch);
  };
  for (int ch : seed) enqueue(ch);
  while (!frontier_.empty()) {
    const int ch = frontier_.back();
    frontier_.pop_back();
    component_channels_.push_back(ch);
    for (Flow* f : on_channel_[ch]) {
      if (f->visited == solve_) continue;
      f->visited = solve_;
      f->assigned = false;
      component_flows_.push_back(f);
      for (int c : f->route) enqueue(c);
    }
  }
}

// Max-min fair rates by progressive filling: repeatedly saturate the channel that offers the
// smallest equal share left / unassigned to the flows still without a rate (the lowest-numbered one
// on a tie), and fix those flows at that share. Each level scans the channels that still have such
// flows, dropping the others as it goes: a tree broadcast's components fill in a few dozen levels
// over about a thousand channels, where a heap of channels cost more in its unpredictable sifting
// than the scans do (and needed re-queuing as shares grew). Channels that begin with one flow are
// left out: they can only offer the whole capacity, which every shared channel offers less than.
void FlowNetwork::fill_progressively() {
  const double capacity = ctx_.config.channel_bandwidth();
  live_.clear();
  for (int ch : component_channels_) {
    left_[ch] = capacity;
    unassigned_[ch] = static_cast<int>(on_channel_[ch].size());
    if (unassigned_[ch] > 1) live_.push_back(ch);
  }
  std::size_t to_assign = component_flows_.size();
  while (to_assign > 0) {
    int best = -1;
    double best_share = 0;
    std::size_t kept = 0;
    for (const int ch : live_) {
      const int n = unassigned_[ch];
      if (n == 0) continue;  // saturated, or all its flows fixed elsewhere
      live_[kept++] = ch;
      // Most channels offer clearly more than the best so far: a multiplication tells, and the
      // division (whose rounding decides near ties) is left to the few that may not.
      if (best >= 0 && left_[ch] > best_share * n * (1 + 1e-9)) continue;
      const double share = left_[ch] / n;
      if (best < 0 || share < best_share || (share == best_share && ch < best)) best = ch, best_share = share;
    }
    live_.resize(kept);
    if (best < 0) break;
    for (Flow* f : on_channel_[best]) {
      if (f->assigned) continue;
      f->assigned = true;
      f->new_rate = best_share;
      --to_assign;
      for (int ch : f->route) {
        left_[ch] -= best_share;
        --unassigned_[ch];
      }
    }
  }
  // Flows on channels of their own only: every shared channel offered less, so the scan would fix
  // them last, each at its channel's whole capacity (left / 1 with nothing taken from it yet).
  for (Flow* f : component_flows_)
    if (!f->assigned) f->assigned = true, f->new_rate = capacity;
}

void FlowNetwork::reshare(const std::vector<int>& seed) {
  collect_component(seed);
  if (component_flows_.empty()) return;
  fill_progressively();
  // Completions are scheduled in flow order, so that simultaneous ones keep their order.
  std::sort(component_flows_.begin(), component_flows_.end(), [](const Flow* a, const Flow* b) { return a->id < b->id; });
  const SimTime now = ctx_.kernel.now();
  for (Flow* f : component_flows_) {
    const double r = f->new_rate;
    if (f->version != 0 && r == f->rate) continue;  // unchanged: its completion event still holds
    f->remaining = std::max(0.0, f->remaining - f->rate * to_seconds(now - f->updated));
    f->updated = now;
    f->rate = r;
    ++f->version;
    // Same expression as NetworkModel::serialization, so a lone flow matches the analytic model.
    const SimTime eta = now + from_seconds(f->remaining / f->rate);
    ctx_.kernel.at(eta, [this, id = f->id, v = f->version] { finish_flow(id, v); });
  }
}

}  // namespace gcsim::machine
