// A ping-pong's simulated time on the analytic model equals the protocol's formula from the
// model's own functions: eager (up to [mpi] eager_limit_bytes) a round trip is 4 (o + G n) + 2 T(h, n);
// rendezvous adds the request-to-send and clear-to-send letters, 2 T(h, 0) each way. T is the
// network model's uncontended time over h hops, o and G the [mpi] overheads. The pair's connection
// set-up is paid by a first exchange, outside the measured loop.
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



TEST(MpiPingPong, RoundTripEqualsTheAnalyticModelsFormulaForEverySizeAndHopCount) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::default_machine_config(), 8, machine::MeshShape{8, 1});
  o.config.network_model = "analytic";
  o.config.mpi.call_overhead = machine::from_seconds(5e-6);
  o.config.mpi.seconds_per_byte = 2e-9;
  const auto interconnect = machine::make_interconnect(o.config);
  machine::Kernel kernel;
  const auto network = machine::make_network_model("analytic", {kernel, *interconnect, o.config, nullptr});
  for (int peer : {1, 3, 7}) {
    const int h = interconnect->hops(0, peer);
    ASSERT_EQ(h, peer);  // a row of 8: rank k is k hops away
    for (int bytes : {0, 1, 1000, 16384, 16385, 100000, 1000000}) {
      const machine::SimTime cpu = o.config.mpi.call_overhead + machine::from_seconds(o.config.mpi.seconds_per_byte * bytes);
      machine::SimTime one_way = 2 * cpu + network->uncontended_time(h, bytes);
      if (bytes > o.config.mpi.eager_limit_bytes) one_way += 2 * network->uncontended_time(h, 0);
      const double expected = machine::to_seconds(2 * one_way);
      EXPECT_NEAR(measured_round_trip(o, peer, bytes, 3), expected, 1e-12) << bytes << " bytes over " << h << " hops";
    }
  }
}

}  // namespace
}  // namespace gcsim::mpi_layer
