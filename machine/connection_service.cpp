#include "machine/connection_service.hpp"

#include <algorithm>

namespace gcsim::machine {

ConnectionService::ConnectionService(const MachineConfig& config, const Interconnect& interconnect)
    : config_(config), net_(interconnect) {
  switch (config.connect_model) {
    case ConnectModel::parallel: break;
    case ConnectModel::serialized: servers_.resize(1); break;
    case ConnectModel::route: servers_.resize(static_cast<std::size_t>(net_.link_count())); break;
    case ConnectModel::servers: {
      const int bx = (net_.width() + config.connect_block_width - 1) / config.connect_block_width;
      const int by = (net_.height() + config.connect_block_height - 1) / config.connect_block_height;
      servers_.resize(static_cast<std::size_t>(bx) * by);
      break;
    }
  }
}

int ConnectionService::server_of(int node) const {
  if (config_.connect_model == ConnectModel::serialized) return 0;
  const int bx = (net_.width() + config_.connect_block_width - 1) / config_.connect_block_width;
  const NodeCoordinates at = net_.coordinates(node);
  return (at.y / config_.connect_block_height) * bx + at.x / config_.connect_block_width;
}

SimTime ConnectionService::duration(int a, int b) const {
  return config_.connect_base + SimTime(net_.hops(a, b)) * config_.connect_per_hop;
}

void ConnectionService::held_by(int a, int b, std::vector<Calendar*>& out) {
  out.clear();
  if (config_.connect_model == ConnectModel::route) {
    // Both directions of a link are one calendar.
    net_.route(a, b, route_);
    for (int ch : route_) out.push_back(&servers_[static_cast<std::size_t>(net_.link_of(ch))]);
    return;
  }
  const int sa = server_of(a), sb = server_of(b);
  out.push_back(&servers_[sa]);
  if (sb != sa) out.push_back(&servers_[sb]);
}

SimTime ConnectionService::set_up(int a, int b, SimTime requested) {
  const SimTime d = duration(a, b);
  if (config_.connect_model == ConnectModel::parallel) return requested + d;
  held_by(a, b, held_);
  const std::span<Calendar* const> all(held_);
  for (Calendar* c : all) c->forget_before(requested);
  const SimTime start = Calendar::earliest_common(all, requested, d);
  for (Calendar* c : all) c->reserve(start, d);
  return start + d;
}

}  // namespace gcsim::machine
