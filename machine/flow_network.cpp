#include "machine/flow_network.hpp"

#include <algorithm>

namespace gcsim::machine {

void FlowNetwork::transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  ++messages_;
  const int hops = ctx_.interconnect.hops(src, dst);
  const SimTime lat = latency(hops);
  if (hops == 0 || bytes <= 0) {
    // Nothing crosses a channel: the latency is all there is.
    ctx_.kernel.after(lat, std::move(on_arrival));
    return;
  }
  if (!solver_) solver_ = std::make_unique<MaxMinSolver>(ctx_.interconnect.channel_count(), channel_bandwidth_);
  const int slot = solver_->open();
  ctx_.interconnect.route(src, dst, solver_->route(slot));
  if (flows_.size() <= static_cast<std::size_t>(slot)) flows_.resize(static_cast<std::size_t>(slot) + 1);
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  f = Flow{};
  f.id = next_id_++;
  f.bytes = bytes;
  f.remaining = static_cast<double>(bytes);
  f.on_arrival = std::move(on_arrival);
  ctx_.kernel.after(lat, [this, slot] { start_flow(slot); });
}

void FlowNetwork::start_flow(int slot) {
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  f.started = f.updated = ctx_.kernel.now();
  solver_->start(slot);
  reschedule();
}

void FlowNetwork::finish_flow(int slot, std::uint64_t version) {
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  if (f.version != version) return;  // rescheduled since
  account(solver_->route(slot), f.bytes, f.started, ctx_.kernel.now());
  solver_->finish(slot);
  reschedule();
  Kernel::Action on_arrival = std::move(f.on_arrival);
  f.version = 0;  // the slot is free; no event carries version 0
  on_arrival();
}

void FlowNetwork::reschedule() {
  changed_.assign(solver_->changed().begin(), solver_->changed().end());
  std::sort(changed_.begin(), changed_.end(), [this](int a, int b) {
    return flows_[static_cast<std::size_t>(a)].id < flows_[static_cast<std::size_t>(b)].id;
  });
  const SimTime now = ctx_.kernel.now();
  for (int slot : changed_) {
    Flow& f = flows_[static_cast<std::size_t>(slot)];
    f.remaining = std::max(0.0, f.remaining - f.rate * to_seconds(now - f.updated));
    f.updated = now;
    f.rate = solver_->rate(slot);
    f.version = ++next_version_;
    // Same expression as NetworkModel::serialization, so a lone flow matches the analytic model.
    const SimTime eta = now + from_seconds(f.remaining / f.rate);
    ctx_.kernel.at(eta, [this, slot, v = f.version] { finish_flow(slot, v); });
  }
}

namespace {
const NetworkModelRegistrar flow_registrar{
    {"flow", "channels shared max-min fairly among the messages crossing them", network_model_factory<FlowNetwork>, 20}};
}  // namespace

}  // namespace gcsim::machine
