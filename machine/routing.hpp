#pragma once
// Routing on the physical network, behind the interface network models use: how many hops a
// message takes and which channels it crosses. The GC's 2D mesh with X-then-Y routing
// (machine/mesh.hpp) is one implementation; another physical topology is another class.
#include <vector>

namespace gcsim::machine {

// The two ends of a directed channel; to is -1 for an id that leads off the network.
struct MeshChannel {
  int from;
  int to;
};

class Routing {
 public:
  virtual ~Routing() = default;
  virtual int nodes() const = 0;
  // Channels crossed from a to b (zero when a == b).
  virtual int hops(int a, int b) const = 0;
  // Channel ids along the route from a to b, in order (empty when a == b).
  virtual void route(int a, int b, std::vector<int>& out) const = 0;
  // Channel ids are 0 .. channel_count() - 1; some may be unused.
  virtual int channel_count() const = 0;
  virtual MeshChannel channel_ends(int channel) const = 0;

  std::vector<int> route(int a, int b) const {
    std::vector<int> out;
    route(a, b, out);
    return out;
  }
};

}  // namespace gcsim::machine
