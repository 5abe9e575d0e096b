#include "machine/topology.hpp"
#include "machine/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

namespace gcsim::machine {
namespace {

TEST(Topology, RingOfFourByHand) {
  // C4: distances 1, 2, 1 from every node; the opposite pair has two shortest paths, so each
  // middle node carries half of it: R = r = 0.5.
  const TopologyMetrics m = exact_metrics(make_topology("ring", 4));
  EXPECT_EQ(m.D, 2);
  EXPECT_DOUBLE_EQ(m.d, 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.R, 0.5);
  EXPECT_DOUBLE_EQ(m.r, 0.5);
  EXPECT_DOUBLE_EQ(m.k, 2);
  EXPECT_EQ(m.B, 2);
}

TEST(Topology, HypercubeOfEightByHand) {
  // Q3: from any node 3 at distance 1, 3 at 2, 1 at 3. Relay loads: sum over the 28 pairs of
  // (distance - 1) = 48 - 28 = 20 interior visits spread evenly: 2.5 per node.
  const TopologyMetrics m = exact_metrics(make_topology("hypercube", 8));
  EXPECT_EQ(m.D, 3);
  EXPECT_DOUBLE_EQ(m.d, 12.0 / 7.0);
  EXPECT_NEAR(m.R, 2.5, 1e-12);
  EXPECT_NEAR(m.r, 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(m.k, 3);
  EXPECT_EQ(m.B, 3);
}

TEST(Topology, BinaryTreeOfSevenByHand) {
  // Root 0, children 1 2, leaves 3 4 5 6. Leaf to leaf across the root is 4 hops.
  // The root relays the 9 pairs between its two subtrees; node 1 relays (3,4) and the 8 pairs
  // between {3,4} and {0,2,5,6}: also 9. Leaves relay nothing.
  const TopologyMetrics m = exact_metrics(make_topology("tree", 7));
  EXPECT_EQ(m.D, 4);
  EXPECT_DOUBLE_EQ(m.R, 9);
  EXPECT_DOUBLE_EQ(m.r, 27.0 / 7.0);
  EXPECT_DOUBLE_EQ(m.k, 12.0 / 7.0);
  EXPECT_EQ(m.B, 2);
}

TEST(Topology, MeshTwoByTwoIsARingOfFour) {
  const TopologyMetrics mesh = exact_metrics(make_topology("mesh", 4));
  const TopologyMetrics ring = exact_metrics(make_topology("ring", 4));
  EXPECT_EQ(mesh.D, ring.D);
  EXPECT_DOUBLE_EQ(mesh.d, ring.d);
  EXPECT_DOUBLE_EQ(mesh.R, ring.R);
}

TEST(Topology, HypercubeOf64HasTheThesisDiameterAndDegree) {
  const TopologyMetrics h = exact_metrics(make_topology("hypercube", 64));
  EXPECT_EQ(h.D, 6);
  EXPECT_EQ(h.k, 6);
  EXPECT_EQ(h.B, 6);
  const TopologyMetrics m = exact_metrics(make_topology("mesh", 64));
  EXPECT_EQ(m.D, 14);
  EXPECT_DOUBLE_EQ(thesis_formulas("mesh", 64).D, 16);
  // The 8x8 mesh's mean distance is exactly (w+h)/3 = 16/3: the formula (2/3)sqrt(N) agrees.
  EXPECT_NEAR(m.d, 16.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(thesis_formulas("hypercube", 64).R, 96);
}

TEST(Topology, TorusWrapsAround) {
  const TopologyMetrics t = exact_metrics(make_topology("torus", 16));  // 4x4 torus
  EXPECT_EQ(t.D, 4);
  EXPECT_DOUBLE_EQ(t.k, 4);
  EXPECT_TRUE(std::isnan(thesis_formulas("torus", 16).D));
}

TEST(Topology, HypercubeNeedsPowerOfTwo) {
  EXPECT_THROW(make_topology("hypercube", 12), std::invalid_argument);
  EXPECT_THROW(parse_topology_kind("star"), std::invalid_argument);
}

TEST(Mapping, MeshOntoItselfHasDilationOne) {
  const Mesh mesh(8, 8);
  const PhysicalMapping m = map_onto(make_topology("mesh", 64), mesh);
  EXPECT_EQ(m.dilation, 1);
  EXPECT_EQ(m.congestion, 1);
}

TEST(Mapping, RingFollowsAHamiltonianCycle) {
  for (auto [w, h] : {std::pair{8, 8}, std::pair{8, 4}, std::pair{4, 2}, std::pair{2, 2}}) {
    const Mesh mesh(w, h);
    const PhysicalMapping m = map_onto(make_topology("ring", w * h), mesh);
    EXPECT_EQ(m.dilation, 1) << w << "x" << h;
    EXPECT_EQ(m.congestion, 1) << w << "x" << h;
  }
}

TEST(Mapping, FoldedTorusKeepsWrapLinksShort) {
  const Mesh mesh(8, 8);
  const PhysicalMapping m = map_onto(make_topology("torus", 64), mesh);
  EXPECT_EQ(m.dilation, 2);
}

TEST(Mapping, EveryProcessorGetsItsOwnNode) {
  const Mesh mesh(8, 4);
  for (const std::string& k : topology_names()) {
    const PhysicalMapping m = map_onto(make_topology(k, 32), mesh);
    std::vector<int> seen(32, 0);
    for (int n : m.node_of) {
      ASSERT_GE(n, 0);
      ASSERT_LT(n, 32);
      ++seen[n];
    }
    for (int s : seen) EXPECT_EQ(s, 1) << k;
  }
}

}  // namespace
}  // namespace gcsim::machine

namespace gcsim::machine {
namespace {

TEST(TopologyRegistry, ListsTheFiveFamiliesOfTable21) {
  EXPECT_EQ(topology_names(), (std::vector<std::string>{"mesh", "torus", "ring", "tree", "hypercube"}));
  EXPECT_EQ(topology_name_list(), "mesh, torus, ring, tree, hypercube");
  for (const auto* f : topology_families()) EXPECT_EQ(&topology_family(f->name()), f);
}

TEST(TopologyRegistry, UnknownNameListsTheKnownOnes) {
  try {
    make_topology("butterfly", 8);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("butterfly"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("mesh, torus, ring, tree, hypercube"), std::string::npos);
  }
  EXPECT_EQ(parse_topology_kind("ring"), "ring");
}

// Every family's graph is undirected, connected and as large as asked.
TEST(TopologyRegistry, EveryFamilyBuildsAnUndirectedGraph) {
  for (const auto* f : topology_families()) {
    const VirtualTopology t = f->graph(16);
    ASSERT_EQ(t.size(), 16) << f->name();
    EXPECT_EQ(t.kind, f->name());
    for (int v = 0; v < t.size(); ++v) {
      for (int w : t.neighbours[v]) {
        EXPECT_NE(v, w) << f->name();
        EXPECT_TRUE(std::binary_search(t.neighbours[w].begin(), t.neighbours[w].end(), v)) << f->name();
      }
    }
    EXPECT_NO_THROW(exact_metrics(t)) << f->name();  // throws if not connected
  }
}

}  // namespace
}  // namespace gcsim::machine
