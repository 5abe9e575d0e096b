#include "machine/connection_service.hpp"

#include <array>

namespace gcsim::machine {

ConnectionService::ConnectionService(const MachineConfig& config, const Mesh& mesh) : config_(config), mesh_(mesh) {
  switch (config.connect_model) {
    case ConnectModel::parallel: break;
    case ConnectModel::serialized: servers_.resize(1); break;
    case ConnectModel::servers: {
      const int bx = (mesh.width() + config.connect_block_width - 1) / config.connect_block_width;
      const int by = (mesh.height() + config.connect_block_height - 1) / config.connect_block_height;
      servers_.resize(static_cast<std::size_t>(bx) * by);
      break;
    }
  }
}

int ConnectionService::server_of(int node) const {
  if (config_.connect_model == ConnectModel::serialized) return 0;
  const int bx = (mesh_.width() + config_.connect_block_width - 1) / config_.connect_block_width;
  return (mesh_.y(node) / config_.connect_block_height) * bx + mesh_.x(node) / config_.connect_block_width;
}

SimTime ConnectionService::duration(int a, int b) const {
  return config_.connect_base + SimTime(mesh_.hops(a, b)) * config_.connect_per_hop;
}

SimTime ConnectionService::set_up(int a, int b, SimTime requested) {
  const SimTime d = duration(a, b);
  if (config_.connect_model == ConnectModel::parallel) return requested + d;
  const int sa = server_of(a), sb = server_of(b);
  std::array<Calendar*, 2> held{&servers_[sa], &servers_[sb]};
  const std::span<Calendar* const> all(held.data(), sa == sb ? 1 : 2);
  for (Calendar* c : all) c->forget_before(requested);
  const SimTime start = Calendar::earliest_common(all, requested, d);
  for (Calendar* c : all) c->reserve(start, d);
  return start + d;
}

}  // namespace gcsim::machine
