#include "machine/analytic_network.hpp"

namespace gcsim::machine {

void AnalyticNetwork::transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) {
  ++messages_;
  const int hops = ctx_.mesh.hops(src, dst);
  const SimTime start = ctx_.kernel.now();
  const SimTime lat = latency(hops);
  const SimTime end = start + lat + (hops > 0 ? serialization(bytes) : 0);  // uncontended_time, lat reused
  if (hops > 0 && (bytes > 0 || ctx_.trace)) {
    ctx_.mesh.route(src, dst, route_);
    account(route_, bytes, start + lat, end);
  }
  ctx_.kernel.at(end, std::move(on_arrival));
}

}  // namespace gcsim::machine
