#pragma once
// The physical 2D mesh of nodes and its dimension-order (X then Y) routing.
// Node n sits at (n % width, n / width). Each node has a directed channel to each neighbour;
// a channel bundles the transputer links that face that neighbour.
#include <cstdint>
#include <vector>

#include "machine/routing.hpp"

namespace gcsim::machine {

enum class Direction : std::uint8_t { east = 0, west = 1, north = 2, south = 3 };

// The name of a channel's direction (channel = node * 4 + direction), as the trace writers print it.
inline const char* direction_name(int channel) {
  static constexpr const char* names[] = {"east", "west", "north", "south"};
  return names[channel % 4];
}

class Mesh final : public Routing {
 public:
  Mesh(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  int nodes() const override { return width_ * height_; }
  int x(int node) const { return node % width_; }
  int y(int node) const { return node / width_; }
  int node_at(int x, int y) const { return y * width_ + x; }

  int hops(int a, int b) const override;
  // Channel ids along the X-then-Y route from a to b (empty when a == b).
  using Routing::route;
  void route(int a, int b, std::vector<int>& out) const override;

  // Channels are numbered node * 4 + direction; some ids (edges of the mesh) are unused.
  int channel_count() const override { return nodes() * 4; }
  int channel(int node, Direction d) const { return node * 4 + static_cast<int>(d); }
  MeshChannel channel_ends(int channel) const override;
  bool channel_exists(int channel) const;

 private:
  int width_;
  int height_;
};

}  // namespace gcsim::machine
