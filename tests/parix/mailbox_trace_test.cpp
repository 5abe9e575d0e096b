// Mailbox::trace_blocked: the layer above the runtime names the time a processor was blocked in
// await() on its own track of the trace (an MPI rank's call), with the peer and bytes it gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

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

// occupy_send_await is occupy(), send() and, with no letter there, await(): the same times, stats
// and trace as the three calls, whether the peer's letter came during the CPU time (no wait) or
// after it (the event that ends the CPU time starts the wait), and the peer sees the same letters.
TEST(MailboxTrace, OccupySendAwaitIsOccupyThenSendThenAwait) {
  const auto dir = test_support::scratch_path("gcsim_mailbox_occupy_send_await_test");
  std::filesystem::create_directories(dir);
  auto exchange = [&](bool compound, const char* name) {
    SimulationOptions o;
    o.config = machine::with_nodes(machine::published_machine_config(), 2);
    o.trace.path = (dir / name).string();
    std::vector<SimTime> replies;
    RunResult r = run_simulated(o, [&](Processor& p) {
      Mailbox& box = *mailbox_of(p);
      std::vector<Letter> got;
      const SimTime work = 300 * machine::kMicrosecond;
      for (int i = 0; i < 6; ++i) {
        if (p.id() == 1) {  // answers each letter after 0, 1 or 2 times processor 0's CPU time
          while (got.empty()) {
            box.collect(got);
            if (got.empty()) box.await({}, "peer", 0);
          }
          got.clear();
          if (i % 3 != 0) box.occupy((i % 3) * work, "answer", false);
          box.send(0, Envelope{}, Bytes(16));
          continue;
        }
        const Bytes data(16);
        const struct : WaitDescription {
          std::string text() const override { return "exchange"; }
        } call;
        SimTime from = -1;
        if (compound) {
          from = box.occupy_send_await(work, "overhead", true, 1, Envelope{}, data, call, 1);
        } else {
          box.occupy(work, "overhead", true);
          box.send(1, Envelope{}, data);
          box.collect(got);
          if (got.empty()) from = p.now(), box.await({}, call, 1);
        }
        if (from >= 0) box.trace_blocked("exchange", from, 1, 16);
        while (got.empty()) {
          box.collect(got);
          if (got.empty()) box.await({}, call, 1);
        }
        got.clear();
        replies.push_back(p.now());
      }
    });
    std::ifstream in(dir / (std::string(name, std::strlen(name) - 5) + ".csv"));
    std::stringstream csv;
    csv << in.rdbuf();
    return std::tuple{replies, r.makespan, r.processors[0].comm, r.processors[0].waiting, csv.str()};
  };
  const auto three = exchange(false, "three.json");
  const auto one = exchange(true, "one.json");
  EXPECT_EQ(std::get<0>(one), std::get<0>(three));
  EXPECT_EQ(std::get<1>(one), std::get<1>(three));
  EXPECT_EQ(std::get<2>(one), std::get<2>(three));
  EXPECT_EQ(std::get<3>(one), std::get<3>(three));
  EXPECT_GT(std::get<3>(three), 0);  // some exchanges waited for the peer
  EXPECT_EQ(std::get<4>(one), std::get<4>(three));
  EXPECT_NE(std::get<4>(three).find("wait,0,1,"), std::string::npos);
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
