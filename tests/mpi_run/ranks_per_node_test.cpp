// Several ranks per node (gcsim mpirun --ranks-per-node K): rank r runs on node r / K; a message
// between two ranks of one node crosses no network and takes the network model's zero-hop time,
// T(0, n) = [network] message_setup, so on the analytic model an eager ping-pong's round trip is
// 4 (o + G n) + 2 T(0, n), and above the eager limit 4 T(0, 0) more (request- and clear-to-send);
// ranks on different nodes pay T(h, n) as with one rank per node. The K ranks share the node's
// CPUs: their computation queues as a processor's threads' does.
#include <gtest/gtest.h>

#include <vector>

#include "apps/mpi/include/mpi.h"
#include "apps/mpi/runtime/rank.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/machine_config.hpp"
#include "machine/network_model.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/mpi_run/ping_pong.hpp"

namespace gcsim::mpi_layer {
namespace {

// 2 nodes in a row, `per_node` ranks on each, on the analytic model.
parix::SimulationOptions packed(int per_node) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::default_machine_config(), 2, machine::MeshShape{2, 1});
  o.config.network_model = "analytic";
  o.config.mpi.call_overhead = machine::from_seconds(5e-6);
  o.config.mpi.seconds_per_byte = 2e-9;
  for (int r = 0; r < 2 * per_node; ++r) o.placement.push_back(r / per_node);  // as gcsim mpirun --ranks-per-node
  return o;
}


TEST(RanksPerNode, RankRRunsOnNodeRDividedByK) {
  const parix::SimulationOptions o = packed(3);
  std::vector<int> node(6, -1);
  std::vector<std::string> name(6);
  parix::run_simulated(o, [&](parix::Processor& p) {
    Rank rank(p, o.config.mpi);
    rank.install();
    char text[MPI_MAX_PROCESSOR_NAME];
    int length = 0;
    MPI_Get_processor_name(text, &length);
    node[static_cast<std::size_t>(p.id())] = rank.node();
    name[static_cast<std::size_t>(p.id())] = text;
    install_registry(nullptr);
  });
  EXPECT_EQ(node, (std::vector<int>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(name[2], "gc-node-0");
  EXPECT_EQ(name[3], "gc-node-1");
}

TEST(RanksPerNode, NodeLocalRoundTripEqualsTheZeroHopFormula) {
  const parix::SimulationOptions o = packed(2);
  const auto interconnect = machine::make_interconnect(o.config);
  machine::Kernel kernel;
  const auto network = machine::make_network_model("analytic", {kernel, *interconnect, o.config, nullptr});
  ASSERT_EQ(network->uncontended_time(0, 1000), o.config.message_setup);  // zero hops: the set-up alone
  for (const int peer : {1, 2}) {  // rank 1 shares node 0; rank 2 is on node 1, one hop away
    const int h = peer / 2;
    for (int bytes : {0, 8, 16384, 16385, 100000}) {
      const machine::SimTime cpu = o.config.mpi.call_overhead + machine::from_seconds(o.config.mpi.seconds_per_byte * bytes);
      machine::SimTime one_way = 2 * cpu + network->uncontended_time(h, bytes);
      if (bytes > o.config.mpi.eager_limit_bytes) one_way += 2 * network->uncontended_time(h, 0);
      EXPECT_NEAR(measured_round_trip(o, peer, bytes, 3), machine::to_seconds(2 * one_way), 1e-12) << bytes << " bytes to rank " << peer;
    }
  }
}

// Each rank computes one simulated second: on a node of one CPU, K ranks take K seconds.
double makespan_of_one_second_each(int per_node) {
  parix::SimulationOptions o = packed(per_node);
  o.config.cpus_per_node = 1;
  return parix::run_simulated(o, [&](parix::Processor& p) {
           Rank rank(p, o.config.mpi);
           rank.install();
           rank.compute(1.0);
           install_registry(nullptr);
         })
      .simulated_seconds();
}

TEST(RanksPerNode, RanksOfOneNodeQueueForItsCpu) {
  EXPECT_DOUBLE_EQ(makespan_of_one_second_each(1), 1.0);
  EXPECT_DOUBLE_EQ(makespan_of_one_second_each(2), 2.0);
  EXPECT_DOUBLE_EQ(makespan_of_one_second_each(3), 3.0);
}

TEST(RanksPerNode, APackingThatLeavesANodeEmptyOrNamesNoNodeIsRefused) {
  parix::SimulationOptions o = packed(2);
  o.placement = {0, 0, 0};  // node 1 empty
  EXPECT_THROW(parix::run_simulated(o, [](parix::Processor&) {}), parix::ParixError);
  o.placement = {0, 0, 2};  // a machine of 2 nodes
  EXPECT_THROW(parix::run_simulated(o, [](parix::Processor&) {}), parix::ParixError);
  o.placement = {0, 0, 1};  // 3 ranks, 2 per node: the last node holds one
  int ran = 0;
  EXPECT_NO_THROW(parix::run_simulated(o, [&](parix::Processor&) { ++ran; }));
  EXPECT_EQ(ran, 3);
}

}  // namespace
}  // namespace gcsim::mpi_layer
