// Connection set-up models on cases worked out by hand (0.55 ms + 0.24 ms per hop on the GC file).
#include "machine/connection_service.hpp"
#include "machine/mesh.hpp"

#include <gtest/gtest.h>

namespace gcsim::machine {
namespace {

constexpr SimTime kBase = 550 * kMicrosecond;
constexpr SimTime kHop = 240 * kMicrosecond;

MachineConfig gc(ConnectModel model, int block_w = 4, int block_h = 4) {
  MachineConfig c = with_nodes(published_machine_config(), 64);
  c.connect_model = model;
  c.connect_block_width = block_w;
  c.connect_block_height = block_h;
  return c;
}

TEST(ConnectionService, TwoNodeConnectionTakesBasePlusHops) {
  const Mesh mesh(8, 8);
  for (ConnectModel m : {ConnectModel::parallel, ConnectModel::serialized, ConnectModel::servers}) {
    const MachineConfig c = gc(m);
    ConnectionService s(c, mesh);
    EXPECT_EQ(s.set_up(0, mesh.node_at(3, 2), 1000), 1000 + kBase + 5 * kHop);
  }
}

TEST(ConnectionService, ParallelSetUpsNeverWait) {
  const Mesh mesh(8, 8);
  const MachineConfig c = gc(ConnectModel::parallel);
  ConnectionService s(c, mesh);
  EXPECT_EQ(s.set_up(0, 1, 0), kBase + kHop);
  EXPECT_EQ(s.set_up(0, 1, 0), kBase + kHop);
}

TEST(ConnectionService, SerializedSetUpsQueueInRequestOrder) {
  const Mesh mesh(8, 8);
  const MachineConfig c = gc(ConnectModel::serialized);
  ConnectionService s(c, mesh);
  const SimTime first = s.set_up(0, 1, 0);              // one hop
  const SimTime second = s.set_up(62, 63, 0);           // far away, but the same server
  const SimTime third = s.set_up(5, 6, second + 1000);  // after the queue emptied: no wait
  EXPECT_EQ(first, kBase + kHop);
  EXPECT_EQ(second, first + kBase + kHop);
  EXPECT_EQ(third, second + 1000 + kBase + kHop);
}

// Blocks of 4x4 on the 8x8 mesh: nodes 0 and 1 share block 0; node 63 is in block 3.
TEST(ConnectionService, ServersSerializeWithinABlockAndNotAcross) {
  const Mesh mesh(8, 8);
  const MachineConfig c = gc(ConnectModel::servers, 4, 4);
  ConnectionService s(c, mesh);
  const SimTime in_block_0 = s.set_up(0, 1, 0);
  const SimTime in_block_3 = s.set_up(62, 63, 0);  // another server: side by side
  const SimTime again_0 = s.set_up(2, 3, 0);       // block 0 is busy until in_block_0
  EXPECT_EQ(in_block_0, kBase + kHop);
  EXPECT_EQ(in_block_3, kBase + kHop);
  EXPECT_EQ(again_0, in_block_0 + kBase + kHop);
  // A set-up across blocks 0 and 3 holds both servers: it waits for the later of the two.
  const SimTime across = s.set_up(0, 63, 0);
  EXPECT_EQ(across, again_0 + kBase + 14 * kHop);
}

TEST(ConnectionService, OneNodeBlocksLetDisjointPairsProceedTogether) {
  const Mesh mesh(8, 8);
  const MachineConfig c = gc(ConnectModel::servers, 1, 1);
  ConnectionService s(c, mesh);
  EXPECT_EQ(s.set_up(0, 1, 0), kBase + kHop);
  EXPECT_EQ(s.set_up(2, 3, 0), kBase + kHop);
  EXPECT_EQ(s.set_up(1, 2, 0), 2 * (kBase + kHop));  // waits for both its ends
}

TEST(ConnectionService, MachineFileChoosesTheModel) {
  std::string text(published_machine_config_text());
  const auto at = text.find("connect_model = \"parallel\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 26, "connect_model = \"servers\"\nconnect_server_block = [4, 2]");
  const MachineConfig c = parse_machine_config(text, "servers.toml");
  EXPECT_EQ(c.connect_model, ConnectModel::servers);
  EXPECT_EQ(c.connect_block_width, 4);
  EXPECT_EQ(c.connect_block_height, 2);
  std::string bad = text;
  bad.replace(bad.find("\"servers\""), 9, "\"telepathy\"");
  EXPECT_THROW(parse_machine_config(bad, "bad.toml"), ConfigError);
}

}  // namespace
}  // namespace gcsim::machine

namespace gcsim::machine {
namespace {

// Route holding on the 8x8 mesh: 0->2 and 1->3 share the link 1-2 (in either direction), so the
// second waits; 8->9 shares nothing with them.
TEST(ConnectionService, RouteHoldingQueuesSetUpsThatShareALink) {
  const Mesh mesh(8, 8);
  MachineConfig c = with_nodes(published_machine_config(), 64);
  c.connect_model = ConnectModel::route;
  ConnectionService s(c, mesh);
  const SimTime two_hops = kBase + 2 * kHop;
  EXPECT_EQ(s.set_up(0, 2, 0), two_hops);
  EXPECT_EQ(s.set_up(3, 1, 0), 2 * two_hops);  // westward over the same link 1-2
  EXPECT_EQ(s.set_up(8, 9, 0), kBase + kHop);
}

}  // namespace
}  // namespace gcsim::machine
