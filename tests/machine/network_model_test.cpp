#include "machine/network_model.hpp"

#include <gtest/gtest.h>

#include "machine/mesh.hpp"

#include <vector>

#include "machine/flow_network.hpp"

namespace gcsim::machine {
namespace {

struct Fixture {
  explicit Fixture(const std::string& model) : config(with_nodes(published_machine_config(), 64)), mesh(8, 8) {
    net = make_network_model(model, {kernel, mesh, config, nullptr});
  }
  MachineConfig config;
  Kernel kernel;
  Mesh mesh;
  std::unique_ptr<NetworkModel> net;
};

TEST(Network, AnalyticTimeIsSetupLatencyHopsAndBandwidth) {
  Fixture f("analytic");
  SimTime arrived = -1;
  const int dst = f.mesh.node_at(3, 2);  // 5 hops
  f.net->transfer(0, dst, 16384, [&] { arrived = f.kernel.now(); });
  f.kernel.run();
  const SimTime expected = 5 * kMicrosecond + 60 * kMicrosecond + 4 * 2 * kMicrosecond +
                           from_seconds(16384.0 / (4 * 35e6 / 16));
  EXPECT_EQ(arrived, expected);
}

TEST(Network, ZeroHopMessagePaysOnlySetup) {
  Fixture f("analytic");
  SimTime arrived = -1;
  f.net->transfer(5, 5, 1000, [&] { arrived = f.kernel.now(); });
  f.kernel.run();
  EXPECT_EQ(arrived, 5 * kMicrosecond);
}

TEST(Network, LoneMessageTakesTheSameTimeUnderFlowAndAnalytic) {
  for (std::int64_t bytes : {0LL, 1LL, 1000LL, 16384LL, 1LL << 20}) {
    for (int dst : {1, 9, 63}) {
      Fixture a("analytic"), fl("flow");
      SimTime ta = -1, tf = -1;
      a.net->transfer(0, dst, bytes, [&] { ta = a.kernel.now(); });
      fl.net->transfer(0, dst, bytes, [&] { tf = fl.kernel.now(); });
      a.kernel.run();
      fl.kernel.run();
      EXPECT_EQ(ta, tf) << bytes << " bytes to node " << dst;
    }
  }
}

TEST(Network, EightMessagesOnOneLinkTakeLongerUnderFlow) {
  const std::int64_t bytes = 16384;
  auto last_arrival = [&](const std::string& model) {
    Fixture f(model);
    SimTime last = 0;
    // Nodes 0..7 of row 0 all send to node 7's east neighbour... all routes share the channel
    // into node 7 from node 6: senders 0..6 and one more from node 6 itself.
    for (int src : {0, 1, 2, 3, 4, 5, 6, 6}) {
      f.net->transfer(src, 7, bytes, [&] { last = std::max(last, f.kernel.now()); });
    }
    f.kernel.run();
    return last;
  };
  const SimTime analytic = last_arrival("analytic");
  const SimTime flow = last_arrival("flow");
  EXPECT_GT(flow, analytic);
  // Eight flows through one channel need at least eight serialization times in all.
  Fixture f("flow");
  EXPECT_GE(flow, 8 * f.net->serialization(bytes));
}

TEST(Network, FlowSharesMaxMinFairly) {
  // Two flows on disjoint channels do not slow each other down.
  Fixture f("flow");
  SimTime t1 = -1, t2 = -1;
  f.net->transfer(0, 1, 8750, [&] { t1 = f.kernel.now(); });
  f.net->transfer(8, 9, 8750, [&] { t2 = f.kernel.now(); });
  f.kernel.run();
  EXPECT_EQ(t1, f.net->uncontended_time(1, 8750));
  EXPECT_EQ(t2, t1);
}

TEST(Network, TwoEqualFlowsOnOneChannelFinishTogetherAtTwiceTheTime) {
  Fixture f("flow");
  SimTime t1 = -1, t2 = -1;
  const std::int64_t bytes = 87500;  // 10 ms alone
  f.net->transfer(0, 1, bytes, [&] { t1 = f.kernel.now(); });
  f.net->transfer(0, 1, bytes, [&] { t2 = f.kernel.now(); });
  f.kernel.run();
  const SimTime alone = f.net->serialization(bytes);
  EXPECT_NEAR(static_cast<double>(t1 - f.net->latency(1)), 2.0 * alone, 2.0);
  EXPECT_NEAR(static_cast<double>(t2), static_cast<double>(t1), 2.0);
}

// Two bottleneck levels: channel 1->2 carries A1, A2 and B (a third of the capacity each), channel
// 2->3 carries B and C; progressive filling fixes the first channel's three flows at c/3, which
// leaves C two thirds. With T the time of one message alone, C finishes at 1.5 T and the other three
// together at 3 T (C's end frees nothing on their bottleneck).
TEST(Network, FlowFillsTheTighterChannelFirst) {
  Fixture f("flow");
  const std::int64_t bytes = 87500;  // 10 ms alone
  const int n1 = f.mesh.node_at(1, 0), n2 = f.mesh.node_at(2, 0), n3 = f.mesh.node_at(3, 0);
  SimTime a1 = -1, a2 = -1, b = -1, c = -1;
  f.net->transfer(n1, n2, bytes, [&] { a1 = f.kernel.now(); });
  f.net->transfer(n1, n2, bytes, [&] { a2 = f.kernel.now(); });
  f.net->transfer(n1, n3, bytes, [&] { b = f.kernel.now(); });
  f.net->transfer(n2, n3, bytes, [&] { c = f.kernel.now(); });
  f.kernel.run();
  const double t = static_cast<double>(f.net->serialization(bytes));
  const double slack = static_cast<double>(f.net->latency(2)) + 100.0;  // start times differ by latencies
  EXPECT_NEAR(static_cast<double>(c), 1.5 * t, slack);
  for (SimTime end : {a1, a2, b}) EXPECT_NEAR(static_cast<double>(end), 3.0 * t, slack);
}

TEST(Network, CountsBytesPerChannel) {
  Fixture f("analytic");
  f.net->transfer(0, 2, 100, [] {});
  f.kernel.run();
  EXPECT_EQ(f.net->channel_bytes()[f.mesh.channel(0, Direction::east)], 100);
  EXPECT_EQ(f.net->channel_bytes()[f.mesh.channel(1, Direction::east)], 100);
  EXPECT_EQ(f.net->messages(), 1u);
}

TEST(Network, UnknownModelListsTheValidOnes) {
  Kernel k;
  Mesh m(2, 1);
  MachineConfig c = with_nodes(published_machine_config(), 2);
  try {
    make_network_model("carrier-pigeon", {k, m, c, nullptr});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("analytic, flow, packet"), std::string::npos);
  }
}

}  // namespace
}  // namespace gcsim::machine

namespace gcsim::machine {
namespace {

// The registry is the one list: every name builds the model of that name, and they all agree on a
// lone message (the property every model promises).
TEST(NetworkRegistry, EveryRegisteredNameBuildsThatModel) {
  EXPECT_EQ(network_model_names(), (std::vector<std::string>{"analytic", "flow", "packet"}));
  for (const std::string& name : network_model_names()) {
    ASSERT_TRUE(is_network_model(name));
    Fixture f(name);
    EXPECT_EQ(f.net->name(), name);
    SimTime arrived = -1;
    f.net->transfer(0, f.mesh.node_at(3, 2), 5000, [&] { arrived = f.kernel.now(); });
    f.kernel.run();
    EXPECT_EQ(arrived, f.net->uncontended_time(5, 5000)) << name;
  }
  EXPECT_FALSE(is_network_model("carrier-pigeon"));
}

// Models see the network only through Interconnect, so a mesh behind the interface routes the same.
TEST(NetworkRegistry, MeshRoutesThroughTheInterconnectInterface) {
  const Mesh mesh(4, 3);
  const Interconnect& r = mesh;
  EXPECT_EQ(r.nodes(), 12);
  EXPECT_EQ(r.hops(0, 11), 5);
  EXPECT_EQ(r.route(0, 11).size(), 5u);
  for (int ch : r.route(0, 11)) EXPECT_GE(r.channel_ends(ch).to, 0);
}

}  // namespace
}  // namespace gcsim::machine
