#pragma once
// The GC's physical interconnect: a 2D mesh of nodes with dimension-order (X then Y) routing.
// Node n sits at (n % width, n / width). Each node has a directed channel to each neighbour;
// a channel bundles the transputer links that face that neighbour. Registered as "mesh", the
// machine file's default ([topology] interconnect).
#include <cstdint>
#include <vector>

#include "machine/interconnect.hpp"

namespace gcsim::machine {

enum class Direction : std::uint8_t { east = 0, west = 1, north = 2, south = 3 };

// The name of a channel's direction (channel = node * 4 + direction), as the trace writers print it.
inline const char* direction_name(int channel) {
  static constexpr const char* names[] = {"east", "west", "north", "south"};
  return names[channel % 4];
}

class Mesh final : public Interconnect {
 public:
  Mesh(int width, int height);

  std::string_view name() const override { return "mesh"; }
  int width() const override { return width_; }
  int height() const override { return height_; }
  int nodes() const override { return width_ * height_; }
  int x(int node) const { return node % width_; }
  int y(int node) const { return node / width_; }
  NodeCoordinates coordinates(int node) const override { return {x(node), y(node)}; }
  int node_at(int x, int y) const override {
    return x >= 0 && x < width_ && y >= 0 && y < height_ ? cell(x, y) : -1;
  }

  int hops(int a, int b) const override;
  // Channel ids along the X-then-Y route from a to b (empty when a == b).
  using Interconnect::route;
  void route(int a, int b, std::vector<int>& out) const override;

  int directions() const override { return 4; }
  // Channels are numbered node * 4 + direction; some ids (edges of the mesh) are unused.
  int channel_count() const override { return nodes() * 4; }
  int channel(int node, Direction d) const { return node * 4 + static_cast<int>(d); }
  ChannelEnds channel_ends(int channel) const override;
  std::string_view channel_label(int channel) const override { return direction_name(channel); }
  // A link is named by its western or southern node: 2 * node for east-west, 2 * node + 1 for
  // north-south, so both directions of a link are one.
  int link_of(int channel) const override;
  int link_count() const override { return nodes() * 2; }

 private:
  int cell(int x, int y) const { return y * width_ + x; }
  int width_;
  int height_;
};

}  // namespace gcsim::machine
