// The runtime's units on their own, without running a simulation: connection matching, in-order
// delivery on a link, the deadlock report, activities and the requests built on them.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "parix/activity.hpp"
#include "parix/sim/connection_matcher.hpp"
#include "parix/sim/deadlock_report.hpp"
#include "parix/sim/in_order_delivery.hpp"
#include "parix/processor.hpp"
#include "parix/sim/request_pool.hpp"

namespace gcsim::parix {
namespace {

TEST(ConnectionMatcher, PairsCallsInCallOrder) {
  ConnectionMatcher<int> m;
  // Processor 0 connects to 1 three times (calls 10, 11, 12) before 1 answers.
  EXPECT_FALSE(m.match_or_wait(0, 1, 7, 10));
  EXPECT_FALSE(m.match_or_wait(0, 1, 7, 11));
  EXPECT_FALSE(m.match_or_wait(0, 1, 7, 12));
  EXPECT_EQ(m.waiting(), 3u);
  EXPECT_EQ(m.match_or_wait(1, 0, 7, 20), 10);
  EXPECT_EQ(m.match_or_wait(1, 0, 7, 21), 11);
  EXPECT_EQ(m.match_or_wait(1, 0, 7, 22), 12);
  EXPECT_EQ(m.waiting(), 0u);
}

TEST(ConnectionMatcher, KeepsTagsAndDirectionsApart) {
  ConnectionMatcher<int> m;
  EXPECT_FALSE(m.match_or_wait(0, 1, 1, 100));
  EXPECT_FALSE(m.match_or_wait(1, 0, 2, 200));  // other tag: waits too
  EXPECT_FALSE(m.match_or_wait(0, 1, 1, 101));  // same direction: never pairs with itself
  EXPECT_FALSE(m.match_or_wait(2, 1, 1, 300));  // other processor
  EXPECT_EQ(m.waiting(), 4u);
  EXPECT_EQ(m.match_or_wait(0, 1, 2, 102), 200);
  EXPECT_EQ(m.match_or_wait(1, 0, 1, 201), 100);
  EXPECT_EQ(m.match_or_wait(1, 2, 1, 202), 300);
  EXPECT_EQ(m.waiting(), 1u);  // 0 -> 1 tag 1, call 101
}

TEST(InOrderDelivery, HoldsAMessageUntilItsPredecessorArrives) {
  InOrderDelivery<std::string> link;
  std::vector<std::string> got;
  auto deliver = [&](std::string&& m) { got.push_back(std::move(m)); };
  link.arrive(2, "c", deliver);
  link.arrive(1, "b", deliver);
  EXPECT_TRUE(got.empty());
  EXPECT_EQ(link.held(), 2u);
  link.arrive(0, "a", deliver);  // releases b and c at once
  EXPECT_EQ(got, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(link.held(), 0u);
  link.arrive(3, "d", deliver);
  EXPECT_EQ(got.back(), "d");
  EXPECT_EQ(link.delivered(), 4);
}

TEST(InOrderDelivery, AnyArrivalOrderDeliversInSendingOrder) {
  const std::vector<int> arrival = {5, 0, 3, 1, 7, 2, 6, 4};
  InOrderDelivery<int> link;
  std::vector<int> got;
  for (int seq : arrival) link.arrive(seq, int(seq), [&](int&& m) { got.push_back(m); });
  for (int i = 0; i < 8; ++i) EXPECT_EQ(got.at(i), i);
}

// The runtime's form (deliver in line): admit says whether a message is next, holding it if not;
// after delivering it the caller releases what waited behind it.
TEST(InOrderDelivery, AdmitHoldsAnEarlyMessageAndReleaseHeldDeliversTheNextOnes) {
  InOrderDelivery<std::string> link;
  std::vector<std::string> got;
  auto deliver = [&](std::string&& m) { got.push_back(std::move(m)); };
  std::string c = "c", b = "b", a = "a";
  EXPECT_FALSE(link.admit(2, c));
  EXPECT_FALSE(link.admit(1, b));
  EXPECT_TRUE(link.holds_any());
  ASSERT_TRUE(link.admit(0, a));
  EXPECT_EQ(a, "a");  // admitted: left with the caller
  deliver(std::move(a));
  link.release_held(deliver);
  EXPECT_EQ(got, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_FALSE(link.holds_any());
  EXPECT_EQ(link.delivered(), 3);
}

TEST(DeadlockReport, NamesEachBlockedProcessCallAndPeer) {
  const std::vector<BlockedProcess> blocked = {
      {0, 0, "recv", 1, 2 * machine::kMillisecond},
      {1, 0, "send", 0, 3 * machine::kMillisecond},
      {1, 2, "join", -1, 0},
  };
  const std::string r = deadlock_report(5 * machine::kMillisecond, blocked);
  EXPECT_NE(r.find("deadlock at simulated time 5 ms"), std::string::npos) << r;
  EXPECT_NE(r.find("processor 0: blocked in recv on processor 1 since 2 ms"), std::string::npos) << r;
  EXPECT_NE(r.find("processor 1: blocked in send to processor 0 since 3 ms"), std::string::npos) << r;
  EXPECT_NE(r.find("processor 1 (thread 2): blocked in join since 0 ms"), std::string::npos) << r;
}

struct CountingWaiter final : detail::Waiter {
  int woken = 0;
  void wake() override { ++woken; }
};

TEST(Activity, CompletesOnceAndWakesWhoeverWaits) {
  detail::Activity a;
  CountingWaiter w;
  EXPECT_FALSE(a.test());
  a.complete();  // nobody waits yet: only the state changes
  EXPECT_TRUE(a.test());
  detail::Activity b;
  b.waiter = &w;
  b.complete();
  b.complete();  // a second completion is ignored
  EXPECT_EQ(w.woken, 1);
}

TEST(Activity, ACancelledActivityWakesItsWaiterOnceAndIgnoresItsCompletion) {
  detail::Activity a;
  CountingWaiter w;
  a.waiter = &w;
  a.cancel();  // whoever waits learns that the activity ended
  a.complete();
  a.cancel();
  EXPECT_EQ(a.state(), detail::Activity::State::cancelled);
  EXPECT_TRUE(a.cancelled());
  EXPECT_FALSE(a.test());
  EXPECT_FALSE(a.running());
  EXPECT_EQ(w.woken, 1);
}

TEST(Activity, ADoneActivityCannotBeCancelled) {
  detail::Activity a;
  a.complete();
  a.cancel();
  EXPECT_EQ(a.state(), detail::Activity::State::done);
}

TEST(Request, ReportsItsCommunicationsState) {
  EXPECT_FALSE(Request().test());
  EXPECT_FALSE(Request().cancelled());
  auto* done = new RequestState;
  auto* withdrawn = new RequestState;
  Request d(done), w(withdrawn);  // deleted with the last Request (RequestState's own release)
  EXPECT_FALSE(d.test());
  done->data = Bytes(3);
  done->complete();
  withdrawn->cancel();
  EXPECT_TRUE(d.test() && d.done() && !d.cancelled());
  EXPECT_TRUE(w.cancelled() && !w.test() && !w.done());
  EXPECT_EQ(d.take().size(), 3u);
  EXPECT_TRUE(w.take().empty());
}

// A backend's own state: where a state goes when its last Request lets go, and where take_into
// puts the caller's old storage, are the backend's (release and recycle).
struct CountingState final : RequestState {
  int* released;
  std::size_t* recycled_capacity;
  CountingState(int* r, std::size_t* c) : released(r), recycled_capacity(c) {}

 private:
  void release() noexcept override {
    ++*released;
    delete this;
  }
  void recycle(Bytes&& storage) noexcept override { *recycled_capacity += storage.capacity(); }
};

TEST(Request, TheBackendsStateDecidesWhereItAndOldStorageGo) {
  int released = 0;
  std::size_t recycled = 0;
  {
    Request a(new CountingState(&released, &recycled));
    Request b = a;
    a.state()->data = Bytes(7);
    a.state()->complete();
    Bytes into;
    into.reserve(100);
    b.take_into(into);
    EXPECT_EQ(into.size(), 7u);
    EXPECT_GE(recycled, 100u);  // into's old storage went to the backend
    a = Request();
    EXPECT_EQ(released, 0);  // b still holds it
  }
  EXPECT_EQ(released, 1);
}

// GCC 12 sees Request's release path (delete when a state has no home) inlined into `a = Request()`
// and warns that b.test() may read freed memory; b still holds a reference, so it cannot.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuse-after-free"
#endif
TEST(RequestPool, CopiesShareAStateWhichTheLastOneRecyclesReset) {
  detail::RequestPool pool;
  RequestState* first = nullptr;
  {
    Request a = pool.take();
    first = a.state();
    Request b = a;  // shares the state
    a.state()->data = Bytes(5);
    a.state()->peer = 3;
    b.state()->complete();
    a = Request();
    EXPECT_TRUE(b.test());  // b still holds it
  }
  Request again = pool.take();  // the same state, back as new
  ASSERT_EQ(again.state(), first);
  EXPECT_TRUE(again.state()->running());
  EXPECT_TRUE(again.state()->data.empty());
  EXPECT_EQ(again.state()->peer, -1);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

}  // namespace
}  // namespace gcsim::parix
