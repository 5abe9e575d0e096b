// Node memory through the PARIX API: reservations by kind, message buffers charged to
// the nodes that hold them, a run over a node's memory stopped at once (enforce) or finished with
// its peak reported (warn), and the broadcast experiment's arguments checked before the run.
#include <gtest/gtest.h>

#include <string>

#include "apps/pipeline/resource_check.hpp"
#include "apps/programs/broadcast_experiment.hpp"
#include "machine/machine_config.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix {
namespace {

constexpr std::int64_t kMB = std::int64_t(1) << 20;

SimulationOptions limited_nodes(int n, machine::MemoryLimit limit = machine::MemoryLimit::enforce) {
  SimulationOptions o;
  o.config = machine::published_machine_config();  // 32 MB a node
  o.config = machine::with_nodes(o.config, n);
  o.memory_limit = limit;
  return o;
}

std::string error_of(const SimulationOptions& o, const std::function<void(Processor&)>& program) {
  try {
    run_simulated(o, program);
  } catch (const OutOfMemoryError& e) {
    return e.what();
  }
  return "";
}

TEST(NodeMemoryRuntime, AReservationIsReleasedWhenItGoesOutOfScope) {
  run_simulated(limited_nodes(1), [](Processor& p) {
    {
      const MemoryReservation a = p.reserve_memory(20 * kMB, "scene");
      EXPECT_THROW((void)p.reserve_memory(20 * kMB, "hemicube"), OutOfMemoryError);
    }
    const MemoryReservation b = p.reserve_memory(30 * kMB, "hemicube");  // the scene's 20 MB came back
    EXPECT_EQ(b.bytes(), 30 * kMB);
  });
}

TEST(NodeMemoryRuntime, TheErrorNamesTheProcessorWhatItHoldsAndTheLimit) {
  const std::string what = error_of(limited_nodes(4), [](Processor& p) {
    const MemoryReservation scene = p.reserve_memory(2 * kMB, "scene");
    if (p.id() == 3) (void)p.reserve_memory(576 * kMB, "hemicube");
  });
  EXPECT_NE(what.find("processor 3: out of node memory: hemicube 576.0 MB asked while holding 2.0 MB (scene 2.0 MB)"),
            std::string::npos)
      << what;
  EXPECT_NE(what.find("the node has 32.0 MB"), std::string::npos) << what;
}

TEST(NodeMemoryRuntime, AMessageIsHeldByTheReceiverUntilReceived) {
  // Processor 1 holds 20 MB and has not yet posted its receive when 16 MB arrive: over its 32 MB.
  const std::string what = error_of(limited_nodes(2), [](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      const Bytes data(16 * kMB);
      Request sent = p.isend(l, data);
      p.wait(sent);
    } else {
      const MemoryReservation held = p.reserve_memory(20 * kMB, "scene");
      p.compute("cycle", 8'000'000'000);  // 100 s: the message arrives meanwhile
      p.recv(l);
    }
  });
  EXPECT_NE(what.find("processor 1: out of node memory: messages received 16.0 MB"), std::string::npos) << what;
  // Received at once (the receive posted first), the same message needs no buffer on node 1.
  EXPECT_NO_THROW(run_simulated(limited_nodes(2), [](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.compute("cycle", 80'000'000);
      p.send(l, Bytes(16 * kMB));
    } else {
      const MemoryReservation held = p.reserve_memory(20 * kMB, "scene");
      EXPECT_EQ(p.recv(l).size(), std::size_t(16 * kMB));
    }
  }));
}

TEST(NodeMemoryRuntime, ABroadcastOfMoreThanANodeHoldsFailsAtOnce) {
  const std::string what = error_of(limited_nodes(4), [](Processor& p) { programs::all_node_broadcast(p, 100 * kMB, BcastAlgo::tree); });
  EXPECT_NE(what.find("out of node memory: broadcast data 100.0 MB"), std::string::npos) << what;
  // 8 MB: the data and one message copy fit in 32 MB.
  EXPECT_NO_THROW(run_simulated(limited_nodes(4), [](Processor& p) { programs::all_node_broadcast(p, 8 * kMB, BcastAlgo::tree); }));
}

TEST(NodeMemoryRuntime, WarnFinishesTheRunAndReportsThePeak) {
  const RunResult r = run_simulated(limited_nodes(4, machine::MemoryLimit::warn),
                                    [](Processor& p) { programs::all_node_broadcast(p, 20 * kMB, BcastAlgo::sequential); });
  EXPECT_GE(r.memory_peak, 40 * kMB);  // the data and a message copy on one node
  EXPECT_EQ(r.memory_capacity, 32 * kMB);
  EXPECT_NE(r.memory_warning.find("node memory over its limit"), std::string::npos) << r.memory_warning;
  EXPECT_TRUE(r.to_json().contains("memory"));
  // Under the limit nothing is reported, and the JSON is as before.
  const RunResult fits = run_simulated(limited_nodes(4), [](Processor& p) { programs::all_node_broadcast(p, 1024, BcastAlgo::tree); });
  EXPECT_TRUE(fits.memory_warning.empty());
  EXPECT_FALSE(fits.to_json().contains("memory"));
}

TEST(BroadcastArguments, SizesParseWithBinaryUnitsAndBadOnesAreRefusedClearly) {
  EXPECT_EQ(programs::parse_message_size("0"), 0);
  EXPECT_EQ(programs::parse_message_size("16KB"), 16384);
  EXPECT_EQ(programs::parse_message_size("10GB"), std::int64_t(10) << 30);
  for (const char* bad : {"-1KB", "-0", "abc", "12XB", "99999999999999999999", "9000000TB"}) {
    try {
      programs::parse_message_size(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find("18446744073709551615"), std::string::npos) << what;
      EXPECT_NE(what.find(std::string("--size ") + bad), std::string::npos) << what;
    }
  }
  try {
    programs::parse_message_size("-1KB");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("must be positive"), std::string::npos) << e.what();
  }
}

TEST(BroadcastArguments, TheNodeLimitIsCheckedBeforeTheHostLimit) {
  const std::int64_t ten_gb = std::int64_t(10) << 30;
  try {
    programs::check_broadcast_resources(ten_gb, 4, 32 * kMB, machine::MemoryLimit::enforce);
    FAIL() << "10 GB per message accepted on 32 MB nodes";
  } catch (const OutOfMemoryError& e) {
    EXPECT_NE(std::string(e.what()).find("broadcast data 10.0 GB"), std::string::npos) << e.what();
  }
  // Warned past the node's memory, the host's is the next limit: 4 x 1 EB cannot be had.
  const std::int64_t exabyte = std::int64_t(1) << 60;
  if (pipeline::host_available_bytes() > 0) {
    try {
      programs::check_broadcast_resources(exabyte, 4, 32 * kMB, machine::MemoryLimit::warn);
      FAIL() << "an exabyte per message accepted";
    } catch (const pipeline::HostMemoryError& e) {
      EXPECT_NE(std::string(e.what()).find("of host memory"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(programs::check_broadcast_resources(16384, 64, 32 * kMB, machine::MemoryLimit::enforce));
}

}  // namespace
}  // namespace gcsim::parix
