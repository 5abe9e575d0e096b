// Receiving into a caller-owned vector (Processor::recv(Link&, Bytes&), Request::take_into) on the
// simulated machine: the caller gets the message, timings match recv(), and the caller's old storage
// goes back to the run's payload pool, where the next message of that size finds it.
#include "parix/sim/simulated_runtime.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

using test_support::bytes_of;

using test_support::published_machine;

// Processor 0 sends `text` after computing `sender_ops` cycles; processor 1 receives it with
// recv(link) or recv(link, into) after `receiver_ops` cycles (800,000 cycles: 10 ms, long enough
// for the message to arrive first). Returns what 1 got and when.
struct Received {
  Bytes data;
  SimTime at = -1;
};
Received exchange(std::string_view text, std::int64_t sender_ops, std::int64_t receiver_ops, bool into) {
  Received got;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.compute("cycle", sender_ops);
      p.send(l, bytes_of(text));
      return;
    }
    p.compute("cycle", receiver_ops);
    if (into) {
      got.data = bytes_of("old contents, longer than the message");
      p.recv(l, got.data);
    } else {
      got.data = p.recv(l);
    }
    got.at = p.now();
  });
  return got;
}

TEST(RecvInto, AMessageNotYetArrivedIsReceivedLikeRecv) {
  const Received plain = exchange("hello", 800'000, 0, false);
  const Received into = exchange("hello", 800'000, 0, true);
  EXPECT_EQ(into.data, bytes_of("hello"));
  EXPECT_EQ(into.at, plain.at);
}

TEST(RecvInto, AMessageAlreadyArrivedIsReceivedLikeRecv) {
  const Received plain = exchange("hello", 0, 800'000, false);
  const Received into = exchange("hello", 0, 800'000, true);
  EXPECT_EQ(into.data, bytes_of("hello"));
  EXPECT_EQ(into.at, plain.at);
}

TEST(RecvInto, AZeroLengthMessageLeavesTheVectorEmpty) {
  const Received into = exchange("", 0, 0, true);
  EXPECT_TRUE(into.data.empty());
}

// The receiver's old storage is recycled: processor 0 sends two messages of one size, waiting for
// an acknowledgement (empty, so it takes no storage) in between; the second message travels in the
// storage the receiver gave up when it received the first.
TEST(RecvInto, TheCallersOldStorageCarriesALaterMessage) {
  const std::byte* old_storage = nullptr;
  const std::byte* second_storage = nullptr;
  Bytes first, second;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send(l, bytes_of("message one"));
      p.recv(l);
      p.send(l, bytes_of("message two"));
      return;
    }
    Bytes into = bytes_of("storage....");  // same size as the messages
    old_storage = into.data();
    p.recv(l, into);
    first = into;
    p.send(l, {});
    p.recv(l, into);
    second = into;
    second_storage = into.data();
  });
  EXPECT_EQ(first, bytes_of("message one"));
  EXPECT_EQ(second, bytes_of("message two"));
  EXPECT_EQ(second_storage, old_storage);
}

// A receive that waits gets its message swapped into its vector as it arrives, and its old
// storage stays with the message's slot for the next message sent in it: whatever the sizes (the
// next message longer than that storage, shorter, empty) and however large the old storage is.
TEST(RecvInto, AWaitingReceiveGetsEverySizeThroughTheStorageItGaveUp) {
  const std::vector<std::string> texts{"eleven char", std::string(40, 'x'), "short", "", std::string(64, 'y'),
                                       std::string(64, 'z')};
  std::vector<Bytes> got;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      for (const std::string& t : texts) {
        p.compute("cycle", 80'000);  // 1 ms: the receive waits for every message
        p.send(l, bytes_of(t));
      }
      return;
    }
    Bytes into(100'000, std::byte{1});  // more storage than a slot keeps
    for (std::size_t i = 0; i < texts.size(); ++i) {
      p.recv(l, into);
      got.push_back(into);
    }
  });
  ASSERT_EQ(got.size(), texts.size());
  for (std::size_t i = 0; i < texts.size(); ++i) EXPECT_EQ(got[i], bytes_of(texts[i])) << i;
}

// On the flow network a short message overtakes a long one sent before it on the same link; the
// link holds it until the long one arrives, then hands both to receives waiting into one vector.
TEST(RecvInto, AnOvertakingMessageReachesAWaitingReceiveInSendingOrder) {
  SimulationOptions o = published_machine(2);
  o.config.network_model = "flow";
  const Bytes long_message(200'000, std::byte{3});
  std::vector<Bytes> got;
  run_simulated(o, [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request first = p.isend(l, long_message);
      Request second = p.isend(l, bytes_of("short"));
      p.wait(first);
      p.wait(second);
      return;
    }
    Bytes into = bytes_of("old storage");
    for (int i = 0; i < 2; ++i) {
      p.recv(l, into);
      got.push_back(into);
    }
  });
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], long_message);
  EXPECT_EQ(got[1], bytes_of("short"));
}

// A receive into a vector that waits needs no request (PostedReceive): it still takes its place
// among the receives posted on its link, and each of a processor's threads waits for its own.
TEST(RecvInto, WaitingReceivesIntoVectorsAndRequestsShareTheLinkInPostingOrder) {
  Bytes by_request, by_thread, by_main;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.compute("cycle", 80'000);  // 1 ms: every receive below is posted first
      for (const char* text : {"first", "second", "third"}) p.send(l, bytes_of(text));
      return;
    }
    Request r = p.irecv(l);
    Thread t = p.spawn([&](Processor& me) { me.recv(l, by_thread); });
    p.compute("cycle", 8'000);  // the thread posts its receive before this one
    p.recv(l, by_main);
    p.wait(r);
    r.take_into(by_request);
    t.join();
  });
  EXPECT_EQ(by_request, bytes_of("first"));
  EXPECT_EQ(by_thread, bytes_of("second"));
  EXPECT_EQ(by_main, bytes_of("third"));
}

// A deadlock while processes wait in receives into vectors names them like any receive, and the
// run unwinds them (the memcheck run of this suite checks it leaves nothing behind).
TEST(RecvInto, ReceivesIntoVectorsThatNeverEndAreReportedAsDeadlock) {
  try {
    run_simulated(published_machine(2), [](Processor& p) {
      Link l = p.connect(1 - p.id());
      Bytes into = bytes_of("old");
      p.recv(l, into);
    });
    FAIL() << "expected a deadlock";
  } catch (const DeadlockError& e) {
    const std::string report = e.what();
    EXPECT_NE(report.find("processor 0: blocked in recv on processor 1"), std::string::npos) << report;
    EXPECT_NE(report.find("processor 1: blocked in recv on processor 0"), std::string::npos) << report;
  }
}

TEST(RecvInto, TakeIntoAfterIrecvSwapsAndTheRequestKeepsNothing) {
  Bytes got = bytes_of("old"), after;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send(l, bytes_of("payload"));
      return;
    }
    Request r = p.irecv(l);
    p.wait(r);
    r.take_into(got);
    after = r.take();
  });
  EXPECT_EQ(got, bytes_of("payload"));
  EXPECT_TRUE(after.empty());
}

// A cancelled receive has no message: take_into empties the vector (its storage is recycled), and
// the link's message goes to the next receive.
TEST(RecvInto, TakeIntoACancelledReceiveEmptiesTheVector) {
  Bytes withdrawn = bytes_of("untouched"), next;
  bool cancelled = false;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send(l, bytes_of("only message"));
      return;
    }
    Request r = p.irecv(l);
    cancelled = p.cancel(r);
    r.take_into(withdrawn);
    p.recv(l, next);
  });
  EXPECT_TRUE(cancelled);
  EXPECT_TRUE(withdrawn.empty());
  EXPECT_EQ(next, bytes_of("only message"));
}

// recv_value receives into the processor's own scratch vector.
TEST(RecvInto, RecvValueStillChecksTheSize) {
  int value = 0;
  std::string error;
  run_simulated(published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send_value(l, 42);
      p.send_value(l, std::int64_t{7});
      return;
    }
    value = p.recv_value<int>(l);
    try {
      p.recv_value<int>(l);
    } catch (const ParixError& e) {
      error = e.what();
    }
  });
  EXPECT_EQ(value, 42);
  EXPECT_NE(error.find("size does not match"), std::string::npos);
}

}  // namespace
}  // namespace gcsim::parix
