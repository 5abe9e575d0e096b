// Mailbox::trace_blocked: the layer above the runtime names the time a processor was blocked in
// await() on its own track of the trace (an MPI rank's call), with the peer and bytes it gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "machine/machine_config.hpp"
#include "parix/mailbox.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::parix {
namespace {

std::string wait_rows(const std::string& csv) {
  std::ifstream in(csv);
  std::string line, rows;
  while (std::getline(in, line)) {
    if (line.rfind("wait,", 0) == 0) rows += line + "\n";
  }
  return rows;
}

TEST(MailboxTrace, TheBlockedIntervalIsAWaitNamedByTheLayerWithItsPeerAndBytes) {
  const auto dir = test_support::scratch_path("gcsim_mailbox_trace_test");
  std::filesystem::create_directories(dir);
  SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), 2);
  o.trace.path = (dir / "t.json").string();
  SimTime arrived = 0;
  run_simulated(o, [&](Processor& p) {
    Mailbox& box = *mailbox_of(p);
    if (p.id() == 0) {
      box.occupy(machine::kMillisecond, "work", false);  // the receiver blocks for at least this long
      box.post(1, Envelope{}, Bytes(64));
      return;
    }
    std::vector<Letter> got;
    const SimTime start = p.now();
    while (got.empty()) {
      box.await({}, "test", 0);
      box.collect(got);
    }
    arrived = p.now();
    box.trace_blocked("MPI_Recv", start, 0, 64);
    box.trace_blocked("MPI_Probe", p.now(), 0, 0);  // no time blocked: no record
  });
  EXPECT_GT(arrived, machine::kMillisecond);
  EXPECT_EQ(wait_rows((dir / "t.csv").string()), "wait,1,0,0," + std::to_string(arrived) + ",64,-1,MPI_Recv,0\n");
  std::filesystem::remove_all(dir);
}

TEST(MailboxTrace, WithoutATraceNothingIsWritten) {
  SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), 1);
  const RunResult r = run_simulated(o, [](Processor& p) {
    Mailbox& box = *mailbox_of(p);
    box.occupy(machine::kMillisecond, "work", false);
    box.trace_blocked("MPI_Recv", 0, -1, 0);  // a run without --trace: the call costs nothing
  });
  EXPECT_EQ(r.makespan, machine::kMillisecond);
}

}  // namespace
}  // namespace gcsim::parix
