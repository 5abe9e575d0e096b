// The packet model on cases whose times can be worked out by hand.
#include "machine/packet_network.hpp"

#include <gtest/gtest.h>

#include "machine/mesh.hpp"

#include <algorithm>
#include <memory>
#include <vector>

namespace gcsim::machine {
namespace {

struct Net {
  explicit Net(const std::string& model, std::int64_t packet_bytes = 1024)
      : config(with_nodes(published_machine_config(), 64)), mesh(8, 8) {
    config.packet_bytes = packet_bytes;
    net = make_network_model(model, {kernel, mesh, config, nullptr});
  }
  // Sends bytes from src to dst now; returns where the arrival time will be written.
  std::shared_ptr<SimTime> send(int src, int dst, std::int64_t bytes) {
    auto t = std::make_shared<SimTime>(-1);
    net->transfer(src, dst, bytes, [this, t] { *t = kernel.now(); });
    return t;
  }
  MachineConfig config;
  Kernel kernel;
  Mesh mesh;
  std::unique_ptr<NetworkModel> net;
};

TEST(PacketNetwork, LoneMessageTakesExactlyTheAnalyticTime) {
  for (std::int64_t packet : {32, 1000, 1024, 4096}) {
    for (std::int64_t bytes : {0LL, 1LL, 1000LL, 1024LL, 1025LL, 16384LL, 1LL << 20}) {
      for (int dst : {0, 1, 9, 63}) {
        Net a("analytic"), p("packet", packet);
        auto ta = a.send(0, dst, bytes);
        auto tp = p.send(0, dst, bytes);
        a.kernel.run();
        p.kernel.run();
        EXPECT_EQ(*ta, *tp) << bytes << " bytes to node " << dst << " in packets of " << packet;
      }
    }
  }
}

TEST(PacketNetwork, CutsMessagesIntoPackets) {
  Net n("packet", 1024);
  n.send(0, 1, 16384);
  n.send(0, 1, 1025);
  n.send(0, 1, 0);  // header only: no packet crosses a channel
  n.kernel.run();
  EXPECT_EQ(static_cast<PacketNetwork&>(*n.net).packets(), 16u + 2u);
}

// A: 0 -> 2 (two hops, through channel 1->2); B: 1 -> 2 (one hop, the same channel), both 16 KB
// at time 0. A is scheduled first, so its 16 packets hold channel 1->2 back to back from
// 65 us + 2 us on; B's first packet is ready at 65 us but the 2 us before A's first packet are
// too short for it, so B's packets follow A's: B arrives one whole message later than A.
TEST(PacketNetwork, SecondMessageOnABusyChannelWaitsForTheFirst) {
  Net n("packet", 1024);
  const std::int64_t bytes = 16384;
  auto ta = n.send(0, 2, bytes);
  auto tb = n.send(1, 2, bytes);
  n.kernel.run();
  EXPECT_EQ(*ta, n.net->uncontended_time(2, bytes));
  EXPECT_EQ(*tb, *ta + n.net->serialization(bytes));
  EXPECT_GT(*tb, n.net->uncontended_time(1, bytes));
}

// Two messages on disjoint routes do not disturb each other.
TEST(PacketNetwork, DisjointRoutesDoNotInteract) {
  Net n("packet");
  auto t1 = n.send(0, 1, 8750);
  auto t2 = n.send(8, 9, 8750);
  n.kernel.run();
  EXPECT_EQ(*t1, n.net->uncontended_time(1, 8750));
  EXPECT_EQ(*t2, *t1);
}

// A short message scheduled after a long one uses an idle gap before the long one's packets
// reach a channel, without delaying them: the long one still takes its uncontended time.
TEST(PacketNetwork, LaterMessageFillsAGapWithoutDelayingEarlierOnes) {
  Net n("packet", 1024);
  const int far = n.mesh.node_at(7, 0);  // 7 hops along row 0
  auto long_msg = n.send(0, far, 4096);
  // Node 6 -> 7 is the last channel of the long route; its packets reach it 6 hop latencies
  // after entering the network. A 100-byte packet (about 11 us) does not fit in 12 us? It does:
  // the gap is 65 + 12 us before the long message's first packet occupies channel 6->7.
  auto short_msg = n.send(6, far, 100);
  n.kernel.run();
  EXPECT_EQ(*long_msg, n.net->uncontended_time(7, 4096));
  EXPECT_EQ(*short_msg, n.net->uncontended_time(1, 100));
}

// Eight 16 KB messages converge on the channel into node 7: it carries one packet at a time, so
// the last arrival is at least eight serialization times after the first packet could enter it.
TEST(PacketNetwork, ConvergingMessagesSerializeOnTheHotChannel) {
  Net a("analytic"), p("packet");
  const std::int64_t bytes = 16384;
  std::vector<std::shared_ptr<SimTime>> ta, tp;
  for (int src : {0, 1, 2, 3, 4, 5, 6, 6}) {
    ta.push_back(a.send(src, 7, bytes));
    tp.push_back(p.send(src, 7, bytes));
  }
  a.kernel.run();
  p.kernel.run();
  auto last = [](const auto& v) {
    SimTime m = 0;
    for (const auto& t : v) m = std::max(m, *t);
    return m;
  };
  EXPECT_GT(last(tp), last(ta));
  EXPECT_GE(last(tp), p.net->latency(1) + 8 * p.net->serialization(bytes));
  // The packets are never slower than the channel allows: the total equals eight back-to-back
  // messages through channel 6->7 plus the time before the first could reach it.
  EXPECT_LE(last(tp), p.net->latency(7) + 8 * p.net->serialization(bytes));
}

// Messages on one link keep their order and a message's packets their order: with equal sizes,
// later messages from the same source arrive later.
TEST(PacketNetwork, BackToBackMessagesFromOneSourceArriveInOrder) {
  Net n("packet", 512);
  std::vector<std::shared_ptr<SimTime>> t;
  for (int i = 0; i < 5; ++i) t.push_back(n.send(0, 27, 3000));
  n.kernel.run();
  for (int i = 1; i < 5; ++i) EXPECT_EQ(*t[i], *t[i - 1] + n.net->serialization(3000)) << i;
}

TEST(PacketNetwork, PacketSizeComesFromTheMachineFile) {
  const MachineConfig c = parse_machine_config(std::string(published_machine_config_text()) , "x.toml");
  EXPECT_EQ(c.packet_bytes, 1024);
  std::string text(published_machine_config_text());
  text.replace(text.find("[network]"), 9, "[network]\npacket_bytes = 0");
  try {
    parse_machine_config(text, "bad.toml");
    FAIL() << "packet_bytes = 0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("packet_bytes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gcsim::machine
