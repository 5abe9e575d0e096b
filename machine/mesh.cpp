#include "machine/mesh.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "machine/interconnect_registry.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::machine {

Mesh::Mesh(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1) throw std::invalid_argument("mesh dimensions must be positive");
}

int Mesh::hops(int a, int b) const { return std::abs(x(a) - x(b)) + std::abs(y(a) - y(b)); }

void Mesh::route(int a, int b, std::vector<int>& out) const {
  out.clear();
  int cx = x(a), cy = y(a);
  const int tx = x(b), ty = y(b);
  while (cx != tx) {
    const Direction d = tx > cx ? Direction::east : Direction::west;
    out.push_back(channel(cell(cx, cy), d));
    cx += tx > cx ? 1 : -1;
  }
  while (cy != ty) {
    const Direction d = ty > cy ? Direction::north : Direction::south;
    out.push_back(channel(cell(cx, cy), d));
    cy += ty > cy ? 1 : -1;
  }
}

ChannelEnds Mesh::channel_ends(int ch) const {
  const int from = ch / 4;
  int nx = x(from), ny = y(from);
  switch (static_cast<Direction>(ch % 4)) {
    case Direction::east: ++nx; break;
    case Direction::west: --nx; break;
    case Direction::north: ++ny; break;
    case Direction::south: --ny; break;
  }
  return {from, node_at(nx, ny)};
}

int Mesh::link_of(int ch) const {
  const ChannelEnds e = channel_ends(ch);
  const bool horizontal = y(e.from) == y(e.to);
  return std::min(e.from, e.to) * 2 + (horizontal ? 0 : 1);
}

namespace {

const InterconnectRegistrar mesh_registrar{
    {"mesh", "the GC's 2D mesh of [topology] mesh = [width, height] nodes, routed X then Y",
     [](const MachineConfig& c) -> std::unique_ptr<Interconnect> { return std::make_unique<Mesh>(c.mesh_width, c.mesh_height); },
     10}};

}  // namespace

}  // namespace gcsim::machine
