// The CPU side of communication ([comm_cpu]): per send, per receive, per connection and
// per byte copied, charged to the node's CPUs, so it competes with compute. Times by hand from the
// published GC: neighbours connect in 790 us; a message pays 65 us + bytes / 8.75 MB/s.
#include <gtest/gtest.h>

#include "machine/machine_config.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

using test_support::kConnectNeighbour;
using test_support::kEmptyMessageNeighbour;

using machine::kMicrosecond;
using machine::SimTime;

SimulationOptions with_costs(SimTime send, SimTime recv, SimTime connect, double ns_per_byte, int cpus = 2) {
  SimulationOptions o;
  o.config = machine::published_machine_config();
  o.config.cpus_per_node = cpus;
  o.config.comm_cpu.send = send;
  o.config.comm_cpu.recv = recv;
  o.config.comm_cpu.connect = connect;
  o.config.comm_cpu.seconds_per_byte = ns_per_byte * 1e-9;
  o.config = machine::with_nodes(o.config, 2);
  return o;
}

Bytes zeros(std::size_t n) { return Bytes(n); }

SimTime wire_time(std::int64_t bytes) { return kEmptyMessageNeighbour + machine::from_seconds(bytes / (4 * 35e6 / 16)); }

TEST(CommCpu, ZeroCostsLeaveTimesAsPublished) {
  SimTime received = -1;
  run_simulated(with_costs(0, 0, 0, 0), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) p.send(l, zeros(1000));
    else {
      p.recv(l);
      received = p.now();
    }
  });
  EXPECT_EQ(received, kConnectNeighbour + wire_time(1000));
}

TEST(CommCpu, SendReceiveAndCopyAddTheirCpuTime) {
  // 100 us to send, 50 us to receive, 10 ns a byte at both ends, 30 us per connection end.
  SimTime received = -1, sent = -1;
  const SimTime copy = 10 * kMicrosecond;  // 1000 bytes x 10 ns
  run_simulated(with_costs(100 * kMicrosecond, 50 * kMicrosecond, 30 * kMicrosecond, 10), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request r = p.isend(l, zeros(1000));
      sent = p.now();  // the CPU copied the message before it left
      p.wait(r);
    } else {
      p.recv(l);
      received = p.now();
    }
  });
  const SimTime connected = kConnectNeighbour + 30 * kMicrosecond;
  EXPECT_EQ(sent, connected + 100 * kMicrosecond + copy);
  EXPECT_EQ(received, connected + 100 * kMicrosecond + copy + wire_time(1000) + 50 * kMicrosecond + copy);
}

TEST(CommCpu, CommunicationCompetesWithComputeForTheCpus) {
  // One CPU per node. On node 1 a thread computes 2 ms from time 0; the message arrives at 855 us,
  // and taking it (50 us of CPU) must wait for the CPU until 2 ms.
  SimTime received = -1;
  run_simulated(with_costs(0, 50 * kMicrosecond, 0, 0, 1), [&](Processor& p) {
    if (p.id() == 0) {
      Link l = p.connect(1);
      p.send(l, zeros(0));
    } else {
      Thread busy = p.spawn([](Processor& t) { t.compute("cycle", 160'000); });  // 2 ms at 80 MHz
      Link l = p.connect(0);
      p.recv(l);
      received = p.now();
      busy.join();
    }
  });
  ASSERT_LT(kConnectNeighbour + kEmptyMessageNeighbour, 2 * machine::kMillisecond);
  EXPECT_EQ(received, 2 * machine::kMillisecond + 50 * kMicrosecond);
}

// Work an exchange does on the CPU (compute_in_comm: an application merging what it received) is
// charged as compute() is, holds a CPU the same way, and counts as communication. 8000 cycles at the
// published 80 MHz: 100 us.
TEST(CommCpu, WorkInsideAnExchangeCountsAsCommunication) {
  const RunResult r = run_simulated(with_costs(0, 0, 0, 0), [&](Processor& p) {
    p.compute("cycle", 8000);
    p.compute_in_comm("cycle", 8000);
  });
  EXPECT_EQ(r.processors[1].compute, 100 * kMicrosecond);
  EXPECT_EQ(r.processors[1].comm, 100 * kMicrosecond);
  EXPECT_EQ(r.processors[1].finish, 200 * kMicrosecond);
  EXPECT_EQ(r.processors[1].ops.at("cycle"), 16000);
}

TEST(CommCpu, MachineFileKeysAreReadAndChecked) {
  const std::string base(machine::published_machine_config_text());
  auto with_table = [&](const std::string& table) {
    std::string text = base;
    const auto at = text.find("[comm_cpu]");
    const auto end = text.find("\n[", at + 1);
    return text.substr(0, at) + table + text.substr(end);
  };
  const machine::MachineConfig c = machine::parse_machine_config(
      with_table("[comm_cpu]\nsend_us = 12.5\nrecv_us = 3\nconnect_us = 40\ncopy_ns_per_byte = 2\n"), "t.toml");
  EXPECT_EQ(c.comm_cpu.send, machine::from_seconds(12.5e-6));
  EXPECT_EQ(c.comm_cpu.recv, 3 * kMicrosecond);
  EXPECT_EQ(c.comm_cpu.connect, 40 * kMicrosecond);
  EXPECT_DOUBLE_EQ(c.comm_cpu.seconds_per_byte, 2e-9);
  try {
    machine::parse_machine_config(with_table("[comm_cpu]\nsend_us = -1\n"), "t.toml");
    FAIL() << "accepted a negative cost";
  } catch (const machine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("send_us"), std::string::npos) << e.what();
  }
  EXPECT_THROW(machine::parse_machine_config(with_table("[comm_cpu]\nsend_ms = 1\n"), "t.toml"), machine::ConfigError);
}

}  // namespace
}  // namespace gcsim::parix
