#include "machine/mesh.hpp"

#include <gtest/gtest.h>

#include "machine/interconnect_registry.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::machine {
namespace {

TEST(Mesh, CoordinatesAreRowMajor) {
  Mesh m(8, 4);
  EXPECT_EQ(m.nodes(), 32);
  EXPECT_EQ(m.x(13), 5);
  EXPECT_EQ(m.y(13), 1);
  EXPECT_EQ(m.node_at(5, 1), 13);
}

TEST(Mesh, RoutesXThenY) {
  Mesh m(4, 4);
  // From (0,0) to (2,3): east, east, north, north, north.
  const std::vector<int> r = m.route(0, m.node_at(2, 3));
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0], m.channel(0, Direction::east));
  EXPECT_EQ(r[1], m.channel(1, Direction::east));
  EXPECT_EQ(r[2], m.channel(2, Direction::north));
  EXPECT_EQ(r[3], m.channel(6, Direction::north));
  EXPECT_EQ(r[4], m.channel(10, Direction::north));
  // And back: west first, then south.
  const std::vector<int> back = m.route(m.node_at(2, 3), 0);
  EXPECT_EQ(back.front(), m.channel(m.node_at(2, 3), Direction::west));
  EXPECT_EQ(back.back(), m.channel(m.node_at(0, 1), Direction::south));
}

TEST(Mesh, RouteLengthIsManhattanDistanceForEveryPair) {
  Mesh m(8, 8);
  for (int a = 0; a < m.nodes(); ++a) {
    for (int b = 0; b < m.nodes(); ++b) {
      const auto r = m.route(a, b);
      ASSERT_EQ(static_cast<int>(r.size()), m.hops(a, b));
      // Consecutive channels connect: each starts where the previous ended.
      int at = a;
      for (int ch : r) {
        ASSERT_TRUE(m.channel_exists(ch));
        const ChannelEnds e = m.channel_ends(ch);
        ASSERT_EQ(e.from, at);
        at = e.to;
      }
      ASSERT_EQ(at, b);
    }
  }
}

TEST(Mesh, EdgeChannelsDoNotExist) {
  Mesh m(2, 1);
  EXPECT_TRUE(m.channel_exists(m.channel(0, Direction::east)));
  EXPECT_FALSE(m.channel_exists(m.channel(0, Direction::west)));
  EXPECT_FALSE(m.channel_exists(m.channel(0, Direction::north)));
  EXPECT_EQ(m.hops(0, 1), 1);
}

// The machine file's default interconnect is this mesh, built from [topology] mesh.
TEST(Mesh, IsTheRegisteredDefaultInterconnect) {
  EXPECT_EQ(interconnect_names(), (std::vector<std::string>{"mesh"}));
  const std::unique_ptr<Interconnect> net = make_interconnect(with_nodes(default_machine_config(), 32));
  EXPECT_EQ(net->name(), "mesh");
  EXPECT_EQ(net->width(), 8);
  EXPECT_EQ(net->height(), 4);
  EXPECT_EQ(net->hops(0, 31), 7 + 3);
  MachineConfig c = default_machine_config();
  c.interconnect = "hypercube";
  EXPECT_THROW(make_interconnect(c), std::invalid_argument);
}

// What the trace writers, placements and the connection service ask of it.
TEST(Mesh, LabelsLinksAndCoordinates) {
  const Mesh m(4, 3);
  EXPECT_EQ(m.channel_label(m.channel(5, Direction::north)), "north");
  EXPECT_EQ(m.coordinates(6).x, 2);
  EXPECT_EQ(m.coordinates(6).y, 1);
  EXPECT_EQ(m.node_at(4, 0), -1);
  EXPECT_EQ(m.node_at(0, -1), -1);
  // A channel and its reverse are one link, named by the western or southern node.
  EXPECT_EQ(m.link_of(m.channel(5, Direction::east)), 2 * 5);
  EXPECT_EQ(m.link_of(m.channel(6, Direction::west)), 2 * 5);
  EXPECT_EQ(m.link_of(m.channel(5, Direction::north)), 2 * 5 + 1);
  EXPECT_EQ(m.link_of(m.channel(9, Direction::south)), 2 * 5 + 1);
  EXPECT_EQ(m.link_count(), 24);
}

}  // namespace
}  // namespace gcsim::machine
