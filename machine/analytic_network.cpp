#include "machine/analytic_network.hpp"

namespace gcsim::machine {

// The common case without a call before the kernel's (a tail call), so that it saves no
// registers: untraced, the pair cached, a message of the last size.
void AnalyticNetwork::transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  RouteCache::Entry* r = routes_.lookup(src, dst);
  if (ctx_.trace || !r || bytes != last_bytes_) [[unlikely]] return transfer_slow(src, dst, bytes, std::move(on_arrival));
  ++messages_;
  SimTime end = ctx_.kernel.now() + r->latency;
  if (r->hops > 0) {
    end += last_serialization_;  // uncontended_time, latency reused
    if (bytes > 0) {
      r->bytes += bytes;
      r->busy += last_serialization_;  // each channel is busy from start + latency to end
    }
  }
  ctx_.kernel.at(end, std::move(on_arrival));
}

// Traced, or the pair or the size new: routes and serialises, then takes the common path.
void AnalyticNetwork::transfer_slow(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  if (ctx_.trace) return transfer_traced(src, dst, bytes, std::move(on_arrival));
  if (channel_bytes_.empty()) {
    channel_bytes_.assign(ctx_.interconnect.channel_count(), 0);
    channel_busy_.assign(ctx_.interconnect.channel_count(), 0);
  }
  RouteCache::Entry& r = routes_.find(src, dst, channel_bytes_, channel_busy_);
  r.latency = latency(r.hops);  // the pair may be new
  last_bytes_ = bytes;
  last_serialization_ = serialization(bytes);
  transfer(src, dst, bytes, std::move(on_arrival));
}

void AnalyticNetwork::transfer_traced(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  ++messages_;
  const int hops = ctx_.interconnect.hops(src, dst);
  const SimTime start = ctx_.kernel.now();
  const SimTime lat = latency(hops);
  const SimTime end = start + lat + (hops > 0 ? serialization(bytes) : 0);  // uncontended_time, lat reused
  if (hops > 0) {
    ctx_.interconnect.route(src, dst, route_);
    account(route_, bytes, start + lat, end);
  }
  ctx_.kernel.at(end, std::move(on_arrival));
}

void AnalyticNetwork::settle() {
  if (!channel_bytes_.empty()) routes_.flush(channel_bytes_, channel_busy_);
}

namespace {
const NetworkModelRegistrar analytic_registrar{
    {"analytic", "latency + size / bandwidth, no contention", network_model_factory<AnalyticNetwork>, 10}};
}  // namespace

}  // namespace gcsim::machine
