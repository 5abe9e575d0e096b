// A process reuses the state of its last send request once nothing else holds it (no pool
// round trip per isend), and never while the program or a message still does: a request the
// program keeps stays what it was, and a message that waits for its receive holds only a
// synchronous send's request.
#include "parix/sim/simulated_runtime.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

using test_support::published_machine;

const Bytes kPayload(64, std::byte{7});

TEST(SendRequestReuse, ADroppedAndDeliveredSendLendsItsStateToTheNext) {
  std::vector<const RequestState*> states;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    for (int i = 0; i < 3; ++i) {
      if (p.id() == 1) {
        p.recv(l);
        continue;
      }
      Request s = p.isend(l, kPayload);
      states.push_back(s.state());
      p.wait(s);
    }
  });
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states[1], states[0]);
  EXPECT_EQ(states[2], states[0]);
}

TEST(SendRequestReuse, ARequestTheProgramKeepsIsNeverReused) {
  bool first_still_done = false, second_ran_until_delivered = false;
  const RequestState* first_state = nullptr;
  const RequestState* second_state = nullptr;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 1) {
      p.recv(l);
      p.recv(l);
      return;
    }
    Request first = p.isend(l, kPayload);
    p.wait(first);
    Request second = p.isend(l, kPayload);
    first_state = first.state();
    second_state = second.state();
    first_still_done = first.test();
    second_ran_until_delivered = !second.test();
    p.wait(second);
    second_ran_until_delivered = second_ran_until_delivered && second.test();
  });
  EXPECT_NE(first_state, second_state);
  EXPECT_TRUE(first_still_done);
  EXPECT_TRUE(second_ran_until_delivered);
}

// The receiver takes its messages long after they arrived: an asynchronous send's message waits in
// the receiver's queue without holding its request, which the sender reuses at once; a synchronous
// one's request is held until the receive takes it (send returns then, not before).
TEST(SendRequestReuse, AMessageWaitingForItsReceiveHoldsOnlyASynchronousSend) {
  std::vector<const RequestState*> states;
  SimTime sync_returned = -1, receiver_took = -1;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 1) {
      p.compute("cycle", 800'000);  // 10 ms: every message arrives first
      for (int i = 0; i < 4; ++i) p.recv(l);
      receiver_took = p.now();
      return;
    }
    for (int i = 0; i < 3; ++i) {
      Request s = p.isend(l, kPayload);
      states.push_back(s.state());
      p.wait(s);
    }
    p.send(l, kPayload);
    sync_returned = p.now();
  });
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states[1], states[0]);
  EXPECT_EQ(states[2], states[0]);
  EXPECT_EQ(sync_returned, receiver_took);
}

}  // namespace
}  // namespace gcsim::parix
