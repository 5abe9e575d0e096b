// The test-only torus through the registry and the Interconnect interface only, as the simulation
// sees it: hops are the wrap-around Manhattan distance, routes as long as that and made of
// channels that exist and chain from a to b, and a channel and its reverse share one link.
#include <cstdlib>
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/mesh.hpp"

namespace gcsim::machine {
namespace {

int ring_distance(int a, int b, int n) {
  const int d = std::abs(a - b);
  return std::min(d, n - d);
}

TEST(TorusInterconnect, IsRegisteredAfterTheMesh) {
  EXPECT_EQ(interconnect_names(), (std::vector<std::string>{"mesh", "torus"}));
  EXPECT_EQ(interconnect_list(), "mesh, torus");
  EXPECT_TRUE(is_interconnect("torus"));
  EXPECT_EQ(make_interconnect("torus", 4, 4)->name(), "torus");
}

TEST(TorusInterconnect, HopsAreTheWrapAroundManhattanDistance) {
  for (auto [w, h] : {std::pair{4, 4}, std::pair{8, 8}, std::pair{5, 3}, std::pair{8, 1}, std::pair{1, 6}, std::pair{2, 2}}) {
    const auto t = make_interconnect("torus", w, h);
    ASSERT_EQ(t->nodes(), w * h);
    for (int a = 0; a < t->nodes(); ++a) {
      for (int b = 0; b < t->nodes(); ++b) {
        const int expected = ring_distance(a % w, b % w, w) + ring_distance(a / w, b / w, h);
        ASSERT_EQ(t->hops(a, b), expected) << w << "x" << h << " " << a << "->" << b;
      }
    }
  }
}

// Corner to corner on 4x4: the mesh goes 3 east and 3 north, the torus one west and one south.
TEST(TorusInterconnect, CornerToCornerIsTwoHopsWhereTheMeshTakesSix) {
  const auto t = make_interconnect("torus", 4, 4);
  const Mesh mesh(4, 4);
  EXPECT_EQ(mesh.hops(0, 15), 6);
  EXPECT_EQ(t->hops(0, 15), 2);
  const std::vector<int> r = t->route(0, 15);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(t->channel_ends(r[0]).to, 3);   // west from (0,0) wraps to (3,0)
  EXPECT_EQ(t->channel_label(r[0]), "west");
  EXPECT_EQ(t->channel_ends(r[1]).to, 15);  // south from (3,0) wraps to (3,3)
  EXPECT_EQ(t->channel_label(r[1]), "south");
}

TEST(TorusInterconnect, RoutesAreAsLongAsTheHopsAndChainThroughValidChannels) {
  for (auto [w, h] : {std::pair{4, 4}, std::pair{8, 8}, std::pair{5, 3}, std::pair{8, 1}, std::pair{2, 2}}) {
    const auto t = make_interconnect("torus", w, h);
    std::vector<int> r;
    for (int a = 0; a < t->nodes(); ++a) {
      for (int b = 0; b < t->nodes(); ++b) {
        t->route(a, b, r);
        ASSERT_EQ(static_cast<int>(r.size()), t->hops(a, b));
        int at = a;
        for (int ch : r) {
          ASSERT_TRUE(t->channel_exists(ch)) << ch;
          const ChannelEnds e = t->channel_ends(ch);
          ASSERT_EQ(e.from, at);
          at = e.to;
        }
        ASSERT_EQ(at, b);
      }
    }
  }
}

TEST(TorusInterconnect, EveryChannelHasAReverseOnTheSameLink) {
  const auto t = make_interconnect("torus", 5, 3);
  std::set<int> links;
  for (int ch = 0; ch < t->channel_count(); ++ch) {
    ASSERT_TRUE(t->channel_exists(ch));
    const ChannelEnds e = t->channel_ends(ch);
    const int link = t->link_of(ch);
    ASSERT_GE(link, 0);
    ASSERT_LT(link, t->link_count());
    links.insert(link);
    int reverse = -1;  // the opposite direction from the far end
    for (int back = e.to * 4; back < e.to * 4 + 4; ++back) {
      if (t->channel_ends(back).to == e.from && t->link_of(back) == link) reverse = back;
    }
    EXPECT_GE(reverse, 0) << "channel " << ch;
  }
  EXPECT_EQ(static_cast<int>(links.size()), t->link_count());  // 2 links per node, each used both ways
}

TEST(TorusInterconnect, ARowHasNoNorthSouthChannels) {
  const auto t = make_interconnect("torus", 8, 1);
  EXPECT_TRUE(t->channel_exists(0 * 4 + 1));   // west from node 0 wraps to node 7
  EXPECT_EQ(t->channel_ends(0 * 4 + 1).to, 7);
  EXPECT_FALSE(t->channel_exists(0 * 4 + 2));  // north would lead back to node 0
  EXPECT_EQ(t->hops(0, 7), 1);
}

TEST(TorusInterconnect, CoordinatesAreRowMajorLikeTheMesh) {
  const auto t = make_interconnect("torus", 8, 4);
  EXPECT_EQ(t->coordinates(13).x, 5);
  EXPECT_EQ(t->coordinates(13).y, 1);
  EXPECT_EQ(t->node_at(5, 1), 13);
  EXPECT_EQ(t->node_at(8, 0), -1);
}

}  // namespace
}  // namespace gcsim::machine
