// Virtual topologies reached from parix, and processors placed on chosen nodes.
#include "parix/virtual_topology.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "machine/mesh.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

using test_support::on_nodes;

TEST(VirtualTopology, EachProcessorSeesItsRingNeighbours) {
  std::vector<std::vector<int>> seen(8);
  run_simulated(on_nodes(8), [&](Processor& p) {
    const auto ring = virtual_topology(p, "ring");
    seen[p.id()] = ring.neighbours();
  });
  for (int v = 0; v < 8; ++v) {
    std::vector<int> expected = {(v + 7) % 8, (v + 1) % 8};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(seen[v], expected) << v;
  }
}

TEST(VirtualTopology, HypercubeNeighboursDifferInOneBitAndTreeHasParents) {
  run_simulated(on_nodes(16), [&](Processor& p) {
    for (int w : virtual_topology(p, "hypercube").neighbours()) EXPECT_EQ(__builtin_popcount(unsigned(w ^ p.id())), 1);
    const auto tree = virtual_topology(p, "tree");
    if (p.id() > 0) {
      EXPECT_EQ(tree.neighbours().front(), (p.id() - 1) / 2);
    }
    EXPECT_EQ(tree.size(), 16);
  });
}

TEST(VirtualTopology, ImpossibleSizesAndUnknownNamesAreParixErrors) {
  EXPECT_THROW(run_simulated(on_nodes(6), [](Processor& p) { virtual_topology(p, "hypercube"); }), ParixError);
  EXPECT_THROW(run_simulated(on_nodes(4), [](Processor& p) { virtual_topology(p, "butterfly"); }), ParixError);
}

// A ring placed by its mapping has every ring edge on neighbouring nodes of the 4x4 mesh.
TEST(Placement, RingPlacementPutsRingNeighboursOnMeshNeighbours) {
  const SimulationOptions o = on_nodes(16);
  const std::vector<int> node_of = topology_placement(o.config, "ring", 16);
  std::vector<int> sorted = node_of;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < 16; ++i) ASSERT_EQ(sorted[i], i);  // a permutation
  const machine::Mesh mesh(4, 4);
  for (int v = 0; v < 16; ++v) EXPECT_EQ(mesh.hops(node_of[v], node_of[(v + 1) % 16]), 1) << v;
}

// Processor 0 sends to processor 1: connect and message times follow the placed nodes' distance.
struct PingTimes {
  SimTime connect = 0, message = 0;
};
PingTimes ping(const std::vector<int>& placement) {
  SimulationOptions o = on_nodes(64);
  o.placement = placement;
  PingTimes t;
  run_simulated(o, [&](Processor& p) {
    if (p.id() > 1) return;
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      t.connect = p.now();
      p.send(l, Bytes(1000));
    } else {
      p.recv(l);
      t.message = p.now();
    }
  });
  t.message -= t.connect;
  return t;
}

TEST(Placement, TimesFollowThePlacedNodesDistance) {
  std::vector<int> far(64);
  for (int i = 0; i < 64; ++i) far[i] = i;
  std::swap(far[1], far[63]);  // processor 1 on node 63: 14 hops from node 0 instead of 1
  const PingTimes near = ping({}), apart = ping(far);
  const auto c = machine::published_machine_config();
  EXPECT_EQ(apart.connect - near.connect, 13 * c.connect_per_hop);
  EXPECT_EQ(apart.message - near.message, 13 * c.hop_latency);
}

TEST(Placement, APlacementMustBeAPermutation) {
  SimulationOptions o = on_nodes(4);
  o.placement = {0, 1, 1, 3};
  try {
    run_simulated(o, [](Processor&) {});
    FAIL() << "no error";
  } catch (const ParixError& e) {
    EXPECT_NE(std::string(e.what()).find("processor 2 on node 1"), std::string::npos) << e.what();
  }
  o.placement = {0, 1, 2};
  EXPECT_THROW(run_simulated(o, [](Processor&) {}), ParixError);
}

}  // namespace
}  // namespace gcsim::parix
