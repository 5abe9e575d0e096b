#include "machine/mesh.hpp"

#include <cstdlib>
#include <stdexcept>

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
    out.push_back(channel(node_at(cx, cy), d));
    cx += tx > cx ? 1 : -1;
  }
  while (cy != ty) {
    const Direction d = ty > cy ? Direction::north : Direction::south;
    out.push_back(channel(node_at(cx, cy), d));
    cy += ty > cy ? 1 : -1;
  }
}

MeshChannel Mesh::channel_ends(int ch) const {
  const int from = ch / 4;
  int nx = x(from), ny = y(from);
  switch (static_cast<Direction>(ch % 4)) {
    case Direction::east: ++nx; break;
    case Direction::west: --nx; break;
    case Direction::north: ++ny; break;
    case Direction::south: --ny; break;
  }
  return {from, (nx >= 0 && nx < width_ && ny >= 0 && ny < height_) ? node_at(nx, ny) : -1};
}

bool Mesh::channel_exists(int ch) const { return ch >= 0 && ch < channel_count() && channel_ends(ch).to >= 0; }

}  // namespace gcsim::machine
