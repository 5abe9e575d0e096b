#pragma once
// The physical interconnect: how the nodes are wired and how a message is routed between them.
// Everything above the wires sees it through this interface only: the network models (hops,
// route, channels), the connection service (hops, route, the undirected link of a channel,
// coordinates for connection-server blocks), virtual-topology placement (coordinates and
// node_at), the trace writers (channel ends and labels, node coordinates) and the heat maps.
//
// The GC's 2D mesh with X-then-Y routing (machine/mesh.hpp) is one implementation. Another is one
// class and one registrar line (machine/interconnect_registry.hpp); the machine file picks it by
// name ([topology] interconnect = "mesh"). tests/interconnects/torus is a complete example.
#include <string_view>
#include <vector>

namespace gcsim::machine {

// The two ends of a directed channel; to is -1 for an id that leads off the network (unused).
struct ChannelEnds {
  int from;
  int to;
};

// Where a node is drawn and placed: a cell of a width() x height() grid.
struct NodeCoordinates {
  int x;
  int y;
};

class Interconnect {
 public:
  virtual ~Interconnect() = default;
  // Its name in the registry and the machine file ("mesh").
  virtual std::string_view name() const = 0;
  virtual int nodes() const = 0;

  // Channels crossed from a to b (zero when a == b).
  virtual int hops(int a, int b) const = 0;
  // Channel ids along the route from a to b, in order (empty when a == b); out is overwritten.
  virtual void route(int a, int b, std::vector<int>& out) const = 0;
  std::vector<int> route(int a, int b) const {
    std::vector<int> out;
    route(a, b, out);
    return out;
  }

  // How many neighbours a node's links are spread over, evenly: one channel bundles
  // links_per_node / directions links (the mesh: 4, east, west, north and south).
  virtual int directions() const = 0;
  // Directed channels are numbered 0 .. channel_count() - 1; some ids may be unused (to == -1).
  virtual int channel_count() const = 0;
  virtual ChannelEnds channel_ends(int channel) const = 0;
  bool channel_exists(int channel) const {
    return channel >= 0 && channel < channel_count() && channel_ends(channel).to >= 0;
  }
  // A channel's direction as the trace writers print it ("east"), for a used channel.
  virtual std::string_view channel_label(int channel) const = 0;
  // The physical link a channel belongs to: a channel and its reverse share one link, numbered
  // 0 .. link_count() - 1. The connection service's route model holds links, not channels.
  virtual int link_of(int channel) const = 0;
  virtual int link_count() const = 0;

  // The coordinates hook: every node is a cell (x, y) of a width() x height() grid, no two on one
  // cell. Trace writers label nodes with it, heat maps draw them there, placements lay virtual
  // topologies out by it and connection servers group nodes in blocks of it.
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual NodeCoordinates coordinates(int node) const = 0;
  // The node at (x, y), or -1 when no node sits there.
  virtual int node_at(int x, int y) const = 0;
};

}  // namespace gcsim::machine
