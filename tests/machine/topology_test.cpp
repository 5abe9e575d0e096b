#include "machine/topology.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gcsim::machine {
namespace {

TEST(Topology, RingOfFourByHand) {
  // C4: distances 1, 2, 1 from every node; the opposite pair has two shortest paths, so each
  // middle node carries half of it: R = r = 0.5.
  const TopologyMetrics m = exact_metrics(make_topology(TopologyKind::ring, 4));
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
  const TopologyMetrics m = exact_metrics(make_topology(TopologyKind::hypercube, 8));
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
  const TopologyMetrics m = exact_metrics(make_topology(TopologyKind::tree, 7));
  EXPECT_EQ(m.D, 4);
  EXPECT_DOUBLE_EQ(m.R, 9);
  EXPECT_DOUBLE_EQ(m.r, 27.0 / 7.0);
  EXPECT_DOUBLE_EQ(m.k, 12.0 / 7.0);
  EXPECT_EQ(m.B, 2);
}

TEST(Topology, MeshTwoByTwoIsARingOfFour) {
  const TopologyMetrics mesh = exact_metrics(make_topology(TopologyKind::mesh, 4));
  const TopologyMetrics ring = exact_metrics(make_topology(TopologyKind::ring, 4));
  EXPECT_EQ(mesh.D, ring.D);
  EXPECT_DOUBLE_EQ(mesh.d, ring.d);
  EXPECT_DOUBLE_EQ(mesh.R, ring.R);
}

TEST(Topology, ThesisIssueFigures) {
  const TopologyMetrics h = exact_metrics(make_topology(TopologyKind::hypercube, 64));
  EXPECT_EQ(h.D, 6);
  EXPECT_EQ(h.k, 6);
  EXPECT_EQ(h.B, 6);
  const TopologyMetrics m = exact_metrics(make_topology(TopologyKind::mesh, 64));
  EXPECT_EQ(m.D, 14);
  EXPECT_DOUBLE_EQ(thesis_formulas(TopologyKind::mesh, 64).D, 16);
  // The 8x8 mesh's mean distance is exactly (w+h)/3 = 16/3: the formula (2/3)sqrt(N) agrees.
  EXPECT_NEAR(m.d, 16.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(thesis_formulas(TopologyKind::hypercube, 64).R, 96);
}

TEST(Topology, TorusWrapsAround) {
  const TopologyMetrics t = exact_metrics(make_topology(TopologyKind::torus, 16));  // 4x4 torus
  EXPECT_EQ(t.D, 4);
  EXPECT_DOUBLE_EQ(t.k, 4);
  EXPECT_TRUE(std::isnan(thesis_formulas(TopologyKind::torus, 16).D));
}

TEST(Topology, HypercubeNeedsPowerOfTwo) {
  EXPECT_THROW(make_topology(TopologyKind::hypercube, 12), std::invalid_argument);
  EXPECT_THROW(parse_topology_kind("star"), std::invalid_argument);
}

TEST(Mapping, MeshOntoItselfHasDilationOne) {
  const Mesh mesh(8, 8);
  const MeshMapping m = map_onto_mesh(make_topology(TopologyKind::mesh, 64), mesh);
  EXPECT_EQ(m.dilation, 1);
  EXPECT_EQ(m.congestion, 1);
}

TEST(Mapping, RingFollowsAHamiltonianCycle) {
  for (auto [w, h] : {std::pair{8, 8}, std::pair{8, 4}, std::pair{4, 2}, std::pair{2, 2}}) {
    const Mesh mesh(w, h);
    const MeshMapping m = map_onto_mesh(make_topology(TopologyKind::ring, w * h), mesh);
    EXPECT_EQ(m.dilation, 1) << w << "x" << h;
    EXPECT_EQ(m.congestion, 1) << w << "x" << h;
  }
}

TEST(Mapping, FoldedTorusKeepsWrapLinksShort) {
  const Mesh mesh(8, 8);
  const MeshMapping m = map_onto_mesh(make_topology(TopologyKind::torus, 64), mesh);
  EXPECT_EQ(m.dilation, 2);
}

TEST(Mapping, EveryProcessorGetsItsOwnNode) {
  const Mesh mesh(8, 4);
  for (TopologyKind k : {TopologyKind::mesh, TopologyKind::torus, TopologyKind::ring, TopologyKind::tree,
                         TopologyKind::hypercube}) {
    const MeshMapping m = map_onto_mesh(make_topology(k, 32), mesh);
    std::vector<int> seen(32, 0);
    for (int n : m.node_of) {
      ASSERT_GE(n, 0);
      ASSERT_LT(n, 32);
      ++seen[n];
    }
    for (int s : seen) EXPECT_EQ(s, 1) << to_string(k);
  }
}

}  // namespace
}  // namespace gcsim::machine
