#include "machine/packet_network.hpp"

#include <algorithm>

namespace gcsim::machine {

PacketNetwork::PacketNetwork(NetworkContext ctx) : NetworkModel(ctx), packet_bytes_(ctx.config.packet_bytes) {}

void PacketNetwork::transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  ++messages_;
  const int hops = ctx_.interconnect.hops(src, dst);
  const SimTime now = ctx_.kernel.now();
  const SimTime lat = latency(hops);
  if (hops == 0 || bytes <= 0) {
    ctx_.kernel.at(now + lat, std::move(on_arrival));
    return;
  }
  if (calendar_.empty()) calendar_.resize(ctx_.interconnect.channel_count());
  ctx_.interconnect.route(src, dst, route_);
  const SimTime hop = ctx_.config.hop_latency;
  // The head of the first packet may enter the first channel after set-up and network latency.
  ready_.assign(route_.size(), 0);
  const SimTime entry = now + ctx_.config.message_setup + ctx_.config.network_latency;
  SimTime first_start = -1, arrival = entry;
  std::int64_t sent = 0;
  while (sent < bytes) {
    const std::int64_t next = std::min(bytes, sent + packet_bytes_);
    const SimTime length = serialization(next) - serialization(sent);
    SimTime at = entry;
    for (std::size_t i = 0; i < route_.size(); ++i) {
      Calendar& channel = calendar_[route_[i]];
      channel.forget_before(now);
      at = channel.take(std::max(at, ready_[i]), length);
      if (first_start < 0) first_start = at;
      ready_[i] = at + length;  // the next packet of this message follows this one
      if (i + 1 < route_.size()) at += hop;
    }
    arrival = at + length;
    sent = next;
    ++packets_;
  }
  account(route_, bytes, first_start, arrival);
  ctx_.kernel.at(arrival, std::move(on_arrival));
}

namespace {
const NetworkModelRegistrar packet_registrar{
    {"packet", "packets queue for each channel of their route (cut-through)", network_model_factory<PacketNetwork>, 30}};
}  // namespace

}  // namespace gcsim::machine
