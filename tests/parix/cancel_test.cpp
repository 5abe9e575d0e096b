// Processor::cancel on the simulated machine (semantics in parix/processor.hpp): small programs on
// two or three neighbouring nodes of the published GC, with times worked out by hand from its
// parameters.
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <utility>

namespace gcsim::parix {
namespace {

using test_support::on_nodes;
using test_support::kConnectNeighbour;
using test_support::kEmptyMessageNeighbour;
using test_support::bytes_of;

using machine::kMicrosecond;
using machine::kMillisecond;

// The published GC: neighbours connect in 0.55 + 0.24 ms; a message pays 5 us set-up and 60 us
// latency, then its bytes cross one channel at 35 MB/s per node over 16 links, 4 per channel.
SimTime bytes_time(std::int64_t n) { return machine::from_seconds(static_cast<double>(n) / (4 * 35e6 / 16)); }

TEST(Cancel, AnUnmatchedReceiveIsWithdrawnAndTheMessageGoesToTheNextReceive) {
  Bytes first, second, withdrawn_data = bytes_of("untouched");
  bool cancelled = false, withdrawn_done = true;
  SimTime after_wait = -1, got_first = -1;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send(l, bytes_of("first"));
      p.send(l, bytes_of("second"));
      return;
    }
    Request withdrawn = p.irecv(l), next = p.irecv(l);
    cancelled = p.cancel(withdrawn);
    p.wait(withdrawn);  // returns at once
    after_wait = p.now();
    withdrawn_done = withdrawn.done();
    withdrawn_data = withdrawn.take();
    p.wait(next);
    got_first = p.now();
    first = next.take();
    second = p.recv(l);
  });
  EXPECT_TRUE(cancelled);
  EXPECT_FALSE(withdrawn_done);
  EXPECT_TRUE(withdrawn_data.empty());
  EXPECT_EQ(after_wait, kConnectNeighbour);
  EXPECT_EQ(first, bytes_of("first"));
  EXPECT_EQ(got_first, kConnectNeighbour + kEmptyMessageNeighbour + bytes_time(5));
  EXPECT_EQ(second, bytes_of("second"));
}

TEST(Cancel, AWithdrawnSendIsNeverDeliveredAndItsSuccessorStillArrivesInOrder) {
  constexpr std::int64_t kLong = 1000;
  bool cancelled = false, still_waiting = false, withdrew_the_spare = false;
  Bytes got;
  SimTime received = -1, send_done = -1;
  RunResult r = run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request long_one = p.isend(l, Bytes(kLong, std::byte{'A'}));
      Request short_one = p.isend(l, bytes_of("B"));
      cancelled = p.cancel(long_one);
      p.wait(short_one);
      send_done = p.now();
      return;
    }
    got = p.recv(l);
    received = p.now();
    Request spare = p.irecv(l);
    p.compute("cycle", 800'000);  // 10 ms: long enough for anything still in flight
    still_waiting = !spare.done();
    withdrew_the_spare = p.cancel(spare);
  });
  EXPECT_TRUE(cancelled);
  EXPECT_EQ(got, bytes_of("B"));
  // The short message overtakes the withdrawn long one in the network, but the link still
  // delivers in sending order: it is released when the long one arrives (and is dropped).
  const SimTime long_arrives = kConnectNeighbour + kEmptyMessageNeighbour + bytes_time(kLong);
  EXPECT_EQ(received, long_arrives);
  EXPECT_EQ(send_done, long_arrives);
  EXPECT_TRUE(still_waiting);
  EXPECT_TRUE(withdrew_the_spare);
  EXPECT_EQ(r.processors[1].finish, received + 10 * kMillisecond);
}

// When the message after a withdrawn one is received, and the sender's clock at the end, with and
// without the cancellation: a withdrawn message still takes its time in the network.
std::pair<SimTime, SimTime> successor_received(const std::string& model, bool withdraw) {
  SimTime received = -1, sender_done = -1;
  run_simulated(on_nodes(2, model), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request long_one = p.isend(l, Bytes(3000, std::byte{'A'}));
      Request short_one = p.isend(l, bytes_of("B"));
      if (withdraw) EXPECT_TRUE(p.cancel(long_one));
      else p.wait(long_one);
      p.wait(short_one);
      sender_done = p.now();
      return;
    }
    if (!withdraw) p.recv(l);
    EXPECT_EQ(p.recv(l), bytes_of("B"));
    received = p.now();
  });
  return {received, sender_done};
}

TEST(Cancel, LaterMessagesArriveAsIfTheWithdrawnOneHadBeenDelivered) {
  for (const std::string model : {"analytic", "flow", "packet"}) {
    EXPECT_EQ(successor_received(model, true), successor_received(model, false)) << model;
  }
}

// A withdrawn message is never charged to the receiver's node: with its 64 KB, the receiver's node
// could not also hold all but 32 KB of its memory.
void hold_nearly_all_memory_after_64_kb_arrive(bool withdraw) {
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request r = p.isend(l, Bytes(1 << 16));
      if (withdraw) {
        EXPECT_TRUE(p.cancel(r));
      }
      return;
    }
    p.compute("cycle", 800'000);  // 10 ms: the 64 KB arrive in 7.6 ms
    auto held = p.reserve_memory(machine::published_machine_config().memory_bytes - (1 << 15), "scene");
  });
}

TEST(Cancel, AWithdrawnMessageIsNeverChargedToTheReceiver) {
  EXPECT_THROW(hold_nearly_all_memory_after_64_kb_arrive(false), OutOfMemoryError);
  EXPECT_NO_THROW(hold_nearly_all_memory_after_64_kb_arrive(true));
}

TEST(Cancel, ACompletedCommunicationCannotBeCancelled) {
  bool send_cancelled = true, recv_cancelled = true, early_cancelled = true, recv_done = false;
  Bytes got, early;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request s = p.isend(l, bytes_of("one"));
      p.wait(s);
      send_cancelled = p.cancel(s);
      p.send(l, bytes_of("two"));
      return;
    }
    Request r = p.irecv(l);
    p.wait(r);
    recv_cancelled = p.cancel(r);
    recv_done = r.done();
    got = r.take();
    p.compute("cycle", 800'000);  // "two" is here by now: the next receive completes when posted
    Request waiting_message = p.irecv(l);
    early_cancelled = p.cancel(waiting_message);
    early = waiting_message.take();
  });
  EXPECT_FALSE(send_cancelled);
  EXPECT_FALSE(recv_cancelled);
  EXPECT_TRUE(recv_done);
  EXPECT_EQ(got, bytes_of("one"));
  EXPECT_FALSE(early_cancelled);
  EXPECT_EQ(early, bytes_of("two"));
}

TEST(Cancel, WaitAnySkipsCancelledRequests) {
  std::size_t first = 99;
  SimTime when = -1;
  Bytes kept;
  run_simulated(on_nodes(3), [&](Processor& p) {
    if (p.id() == 0) {
      Link a = p.connect(1), b = p.connect(2);
      Request ra = p.irecv(a), rb = p.irecv(b);
      EXPECT_TRUE(p.cancel(ra));
      Request* both[] = {&ra, &rb};
      first = p.wait_any(both);  // processor 1's message comes first, but ra no longer takes it
      when = p.now();
      kept = p.recv(a);  // it waited on the link for the next receive
      Request* none[] = {&ra};
      EXPECT_THROW(p.wait_any(none), ParixError);
      return;
    }
    Link l = p.connect(0);
    // Both are late, so that processor 0 has posted its receives: processor 1 by 5 ms, 2 by 10 ms.
    p.compute("cycle", p.id() == 1 ? 400'000 : 800'000);
    p.send(l, bytes_of(p.id() == 1 ? "one" : "two"));
  });
  EXPECT_EQ(first, 1u);
  EXPECT_GE(when, 10 * kMillisecond);
  EXPECT_EQ(kept, bytes_of("one"));
}

TEST(Cancel, ACancelledReceiveIsNoDeadlock) {
  RunResult r = run_simulated(on_nodes(2), [](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request never = p.irecv(l);  // processor 1 sends nothing
      p.cancel(never);
      p.wait(never);
    }
  });
  EXPECT_EQ(r.makespan, kConnectNeighbour);
}

TEST(Cancel, ARealDeadlockIsReportedWithoutTheCancelledReceive) {
  try {
    run_simulated(on_nodes(3), [](Processor& p) {
      if (p.id() == 0) {
        Link to_1 = p.connect(1), to_2 = p.connect(2);
        Request withdrawn = p.irecv(to_1);
        p.cancel(withdrawn);
        p.recv(to_2);
      } else if (p.id() == 1) {
        Link l = p.connect(0);
      } else {
        Link l = p.connect(0);
        p.recv(l);
      }
    });
    FAIL() << "expected a deadlock";
  } catch (const DeadlockError& e) {
    const std::string report = e.what();
    EXPECT_NE(report.find("processor 0: blocked in recv on processor 2"), std::string::npos) << report;
    EXPECT_NE(report.find("processor 2: blocked in recv on processor 0"), std::string::npos) << report;
    EXPECT_EQ(report.find("on processor 1"), std::string::npos) << report;
  }
}

TEST(Cancel, AnotherThreadCancellingARequestWakesItsWaiter) {
  SimTime woke = -1;
  bool cancelled = false;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 1) return;  // never sends
    Request r = p.irecv(l);
    Thread watchdog = p.spawn([&](Processor& q) {
      q.compute("cycle", 80'000);  // 1 ms
      cancelled = q.cancel(r);
    });
    p.wait(r);
    woke = p.now();
  });
  EXPECT_TRUE(cancelled);
  EXPECT_EQ(woke, kConnectNeighbour + kMillisecond);
}

TEST(Cancel, AnEmptyRequestIsAnError) {
  EXPECT_THROW(run_simulated(on_nodes(1), [](Processor& p) {
                 Request none;
                 p.cancel(none);
               }),
               ParixError);
}

}  // namespace
}  // namespace gcsim::parix
