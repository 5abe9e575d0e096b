// The waiting counter (docs/run-records.md): of the time a processor is blocked, the part before
// its peer acted (sent the message that ends a receive, asked for the link). Checked against the
// published machine's exact times: a receive that waits while the sender computes 1 ms waits
// exactly 1 ms, and the rest of its blocked time is the message's transfer.
#include <gtest/gtest.h>

#include "parix/mailbox.hpp"
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

// Addressed mail (the MPI layer's): an await ended by a letter waited until its sender posted it.
RunResult mail_after(std::int64_t sender_cycles, std::int64_t receiver_cycles) {
  return run_simulated(on_nodes(2), [&](Processor& p) {
    Mailbox& box = *mailbox_of(p);
    if (p.id() == 0) {
      p.compute("cycle", sender_cycles);
      Request sent = box.post(1, Envelope{}, {});
      while (sent.state()->running()) box.await(std::span(&sent, 1), "send", 1);
      return;
    }
    p.compute("cycle", receiver_cycles);
    std::vector<Letter> got;
    for (box.collect(got); got.empty(); box.collect(got)) box.await({}, "recv", 0);
  });
}

TEST(WaitingCounter, AnAwaitForMailWaitsUntilThePeerPosts) {
  const RunResult r = mail_after(kOneMillisecondOfCycles, 0);
  EXPECT_EQ(r.processors[1].waiting, kMillisecond);
  EXPECT_GT(r.processors[1].comm, r.processors[1].waiting);  // then the set-up and the transfer
  EXPECT_EQ(r.processors[0].waiting, 0);  // its letter's delivery is the network's doing
}

TEST(WaitingCounter, MailAlreadyOnItsWayIsNoWaiting) {
  const RunResult r = mail_after(0, 1);
  EXPECT_EQ(r.processors[1].waiting, 0);
  EXPECT_GT(r.processors[1].comm, 0);
}

}  // namespace
}  // namespace gcsim::parix
