// A test-only physical interconnect: the nodes' grid as a 2D torus, each row and column closed
// into a ring by a wrap-around link, routed dimension by dimension (X, then Y), each the shorter
// way round (east or north on a tie). It exists to prove that an interconnect is one class and
// one registrar line: nothing outside tests/interconnects/torus names it, yet a machine file with
// [topology] interconnect = "torus" runs every application, placement and trace on it.
#include <cstdlib>
#include <memory>

#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::machine {
namespace {

// Channels are numbered as the mesh's: node * 4 + direction (east, west, north, south = +y, -y).
class Torus final : public Interconnect {
 public:
  Torus(int width, int height) : w_(width), h_(height) {}

  std::string_view name() const override { return "torus"; }
  int nodes() const override { return w_ * h_; }
  int width() const override { return w_; }
  int height() const override { return h_; }
  NodeCoordinates coordinates(int node) const override { return {node % w_, node / w_}; }
  int node_at(int x, int y) const override { return x >= 0 && x < w_ && y >= 0 && y < h_ ? y * w_ + x : -1; }

  int hops(int a, int b) const override {
    const NodeCoordinates p = coordinates(a), q = coordinates(b);
    return ring_distance(p.x, q.x, w_) + ring_distance(p.y, q.y, h_);
  }

  void route(int a, int b, std::vector<int>& out) const override {
    out.clear();
    NodeCoordinates at = coordinates(a);
    const NodeCoordinates to = coordinates(b);
    const int east = steps_forward(at.x, to.x, w_), north = steps_forward(at.y, to.y, h_);
    while (at.x != to.x) {
      const bool forward = 2 * east <= w_;
      out.push_back(channel(node_at(at.x, at.y), forward ? 0 : 1));
      at.x = (at.x + (forward ? 1 : w_ - 1)) % w_;
    }
    while (at.y != to.y) {
      const bool forward = 2 * north <= h_;
      out.push_back(channel(node_at(at.x, at.y), forward ? 2 : 3));
      at.y = (at.y + (forward ? 1 : h_ - 1)) % h_;
    }
  }

  int directions() const override { return 4; }
  int channel_count() const override { return nodes() * 4; }
  // A dimension of extent 1 has no channels: its wrap-around would lead a node to itself.
  ChannelEnds channel_ends(int ch) const override {
    const int from = ch / 4;
    const NodeCoordinates p = coordinates(from);
    const int d = ch % 4;
    if ((d < 2 && w_ == 1) || (d >= 2 && h_ == 1)) return {from, -1};
    switch (d) {
      case 0: return {from, node_at((p.x + 1) % w_, p.y)};
      case 1: return {from, node_at((p.x + w_ - 1) % w_, p.y)};
      case 2: return {from, node_at(p.x, (p.y + 1) % h_)};
      default: return {from, node_at(p.x, (p.y + h_ - 1) % h_)};
    }
  }
  std::string_view channel_label(int ch) const override {
    static constexpr std::string_view names[] = {"east", "west", "north", "south"};
    return names[ch % 4];
  }
  // The link east of a node is 2 * node, the one north of it 2 * node + 1: a west channel is its
  // western neighbour's east link, a south channel its southern neighbour's north link.
  int link_of(int ch) const override {
    const int d = ch % 4;
    return d == 0 || d == 2 ? 2 * (ch / 4) + d / 2 : 2 * channel_ends(ch).to + d / 2;
  }
  int link_count() const override { return nodes() * 2; }

 private:
  static int steps_forward(int from, int to, int extent) { return ((to - from) % extent + extent) % extent; }
  static int ring_distance(int from, int to, int extent) {
    const int forward = steps_forward(from, to, extent);
    return forward <= extent - forward ? forward : extent - forward;
  }
  static int channel(int node, int direction) { return node * 4 + direction; }
  int w_;
  int h_;
};

const InterconnectRegistrar torus_registrar{
    {"torus", "the nodes' grid closed into rings in x and y, routed X then Y the shorter way (a test-only interconnect)",
     [](const MachineConfig& c) -> std::unique_ptr<Interconnect> { return std::make_unique<Torus>(c.mesh_width, c.mesh_height); }}};

}  // namespace
}  // namespace gcsim::machine
