// The waiting counter (docs/run-records.md): of the time a processor is blocked, the part before
// its peer acted (sent the message that ends a receive, asked for the link). Checked against the
// published machine's exact times: a receive that waits while the sender computes 1 ms waits
// exactly 1 ms, and the rest of its blocked time is the message's transfer.
#include <gtest/gtest.h>

#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

using machine::kMillisecond;
using test_support::kConnectNeighbour;
using test_support::kEmptyMessageNeighbour;
using test_support::on_nodes;

constexpr std::int64_t kOneMillisecondOfCycles = 80'000;  // at the published 80 MHz

TEST(WaitingCounter, AReceiveWaitsUntilThePeerSends) {
  for (const bool into_vector : {false, true}) {  // a request's receive, and recv(link, into)
    const RunResult r = run_simulated(on_nodes(2), [&](Processor& p) {
      Link l = p.connect(1 - p.id());
      if (p.id() == 0) {
        p.compute("cycle", kOneMillisecondOfCycles);
        p.send(l, {});
      } else if (into_vector) {
        Bytes into;
        p.recv(l, into);
      } else {
        p.recv(l);
      }
    });
    const ProcessorStats& receiver = r.processors[1];
    EXPECT_EQ(receiver.waiting, kMillisecond) << "into a vector: " << into_vector;
    EXPECT_EQ(receiver.comm - receiver.waiting, kConnectNeighbour + kEmptyMessageNeighbour);
    EXPECT_EQ(r.processors[0].waiting, 0);  // its receiver was there: the send only moved bytes
    EXPECT_EQ(r.processors[0].comm, kConnectNeighbour + kEmptyMessageNeighbour);
  }
}

TEST(WaitingCounter, AMessageAlreadyOnItsWayIsNoWaiting) {
  const RunResult r = run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send(l, {});
    } else {
      p.compute("cycle", 1);  // posts its receive just after the send call: the message is in flight
      p.recv(l);
    }
  });
  EXPECT_EQ(r.processors[1].waiting, 0);
  EXPECT_GT(r.processors[1].comm, kConnectNeighbour);
}

TEST(WaitingCounter, AConnectWaitsForItsPartnerToAsk) {
  const RunResult r = run_simulated(on_nodes(2), [&](Processor& p) {
    if (p.id() == 1) p.compute("cycle", kOneMillisecondOfCycles);  // asks 1 ms late
    p.connect(1 - p.id());
  });
  EXPECT_EQ(r.processors[0].waiting, kMillisecond);
  EXPECT_EQ(r.processors[0].comm - r.processors[0].waiting, kConnectNeighbour);
  EXPECT_EQ(r.processors[1].waiting, 0);
}

}  // namespace
}  // namespace gcsim::parix
