#include "parix/sim/link_table.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "parix/collectives.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

// An end whose business the test decides.
struct FakeEnd {
  bool open = true;
  std::int64_t peer_end = -1;
  bool busy = false;
  int value = 0;
  bool idle(const FakeEnd&) const { return !busy; }
};

TEST(LinkTable, APairIsEachOthersPeer) {
  LinkTable<FakeEnd> t;
  const auto [a, b] = t.open_pair();
  ASSERT_NE(t.find(a), nullptr);
  ASSERT_NE(t.find(b), nullptr);
  EXPECT_EQ(t.find(a)->peer_end, b);
  EXPECT_EQ(t.find(b)->peer_end, a);
  EXPECT_EQ(t.find(-1), nullptr);
  EXPECT_EQ(t.find(b + 1), nullptr);
}

TEST(LinkTable, SlotsAreReusedOnlyWhenBothEndsAreClosedAndIdle) {
  LinkTable<FakeEnd> t;
  const auto [a, b] = t.open_pair();
  t.find(b)->busy = true;  // e.g. a message still travelling to b
  t.close(a);
  EXPECT_EQ(t.open_ends(), 2u);  // b is open
  t.close(b);
  EXPECT_EQ(t.open_ends(), 2u);  // b is not idle
  t.find(b)->busy = false;
  t.release_if_done(b);
  EXPECT_EQ(t.open_ends(), 0u);
  EXPECT_EQ(t.find(a), nullptr);  // stale handles
  EXPECT_EQ(t.find(b), nullptr);

  const auto [c, d] = t.open_pair();
  EXPECT_EQ(t.slots(), 2u);  // the freed slots, with fresh ends
  EXPECT_NE(c, a);
  EXPECT_NE(c, b);
  EXPECT_TRUE(t.find(c)->open);
  EXPECT_FALSE(t.find(d)->busy);
  t.close(a);  // a stale close touches nothing
  EXPECT_TRUE(t.find(c)->open && t.find(d)->open);
}

// A Link keeps its end's hint (Link::hint): through it a live handle finds its end without the
// slot's look-up, and a handle whose slot was reused since finds nothing, as find does.
TEST(LinkTable, AHintFindsTheLiveEndAndNeverAReusedSlotsNewEnd) {
  LinkTable<FakeEnd> t;
  const auto [a, b] = t.open_pair();
  const void* hint_a = t.hint_of(a);
  EXPECT_EQ(t.find(a, hint_a), t.find(a));
  EXPECT_EQ(t.find(b, nullptr), t.find(b));  // no hint: the look-up
  t.close(a);
  t.close(b);
  const auto [c, d] = t.open_pair();  // the same slots, a new generation
  EXPECT_EQ(t.find(a, hint_a), nullptr);
  EXPECT_EQ(t.find(c, t.hint_of(c)), t.find(c));
  EXPECT_EQ(t.find(d, t.hint_of(d)), t.find(d));
}

// Through its hint a link is still checked on every use: another processor's link is refused.
TEST(LinkTable, ALinkOfAnotherProcessorIsRefusedOnUse) {
  Link* of_zero = nullptr;
  std::string error;
  run_simulated(test_support::published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      of_zero = &l;
      p.recv(l);  // keeps l alive until 1 has tried it
      return;
    }
    p.compute("cycle", 1000);  // 0 has published its link
    try {
      p.send(*of_zero, {});
    } catch (const ParixError& e) {
      error = e.what();
    }
    p.send(l, {});
  });
  EXPECT_NE(error.find("processor 1: send on a link owned by processor 0"), std::string::npos) << error;
}

// A moved-from link names no end (handle -1, no hint), so the runtime, which no longer asks
// Link::valid on every send and receive, refuses it as not open; the link it moved to works.
TEST(LinkTable, AMovedFromLinkIsRefusedAsNotOpen) {
  std::string error;
  std::int64_t moved_from_handle = 0;
  const void* moved_from_hint = &error;
  run_simulated(test_support::published_machine(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    Link moved = std::move(l);
    if (p.id() == 1) {
      moved_from_handle = l.handle();
      moved_from_hint = l.hint();
      try {
        p.send(l, {});
      } catch (const ParixError& e) {
        error = e.what();
      }
      p.send(moved, {});
    } else {
      p.recv(moved);
    }
  });
  EXPECT_EQ(moved_from_handle, -1);
  EXPECT_EQ(moved_from_hint, nullptr);
  EXPECT_NE(error.find("processor 1: send on a link that is not open"), std::string::npos) << error;
}

TEST(LinkTable, AThousandPairsOpenedAndClosedInTurnUseTwoSlots) {
  LinkTable<FakeEnd> t;
  for (int i = 0; i < 1000; ++i) {
    const auto [a, b] = t.open_pair();
    t.find(a)->value = i;
    t.close(b);
    t.close(a);
  }
  EXPECT_EQ(t.slots(), 2u);
}

using test_support::published_machine;

Bytes number(int i) {
  Bytes b(sizeof i);
  std::memcpy(b.data(), &i, sizeof i);
  return b;
}

int number_of(const Bytes& b) {
  int i = -1;
  if (b.size() == sizeof i) std::memcpy(&i, b.data(), sizeof i);
  return i;
}

// The thesis's way: a connection for every message. Asynchronous sends on a link the sender closes
// at once leave their message in flight; its pair is reused only after the receive.
TEST(LinkTable, AConnectionPerMessageReusesTheSameSlots) {
  std::vector<int> got;
  const RunResult r = run_simulated(published_machine(2), [&](Processor& p) {
    for (int i = 0; i < 500; ++i) {
      Link l = p.connect(1 - p.id());
      if (p.id() == 0) {
        Request sent = p.isend(l, number(i));
        (void)sent;
      } else {
        got.push_back(number_of(p.recv(l)));
      }
    }
  });
  ASSERT_EQ(got.size(), 500u);
  for (int i = 0; i < 500; ++i) EXPECT_EQ(got[std::size_t(i)], i);
  EXPECT_LE(r.link_end_slots, 4);
}

// Every node's link to every other, per message, as the radiosity's sequential broadcast opens them.
TEST(LinkTable, BroadcastsThatConnectPerMessageHoldAboutOneRoundOfLinks) {
  constexpr int kNodes = 8, kRounds = 50;
  std::vector<int> sums(kNodes, 0);
  const RunResult r = run_simulated(published_machine(kNodes), [&](Processor& p) {
    CollectiveOptions o;
    o.connect_per_message = true;
    for (int round = 0; round < kRounds; ++round) {
      const Bytes mine = number(p.id() + round);
      const std::vector<Bytes> all = allgather(p, mine, o);
      for (const Bytes& b : all) sums[std::size_t(p.id())] += number_of(b);
    }
  });
  const int expected = kRounds * (kNodes * (kNodes - 1) / 2) + kNodes * (kRounds * (kRounds - 1) / 2);
  for (int s : sums) EXPECT_EQ(s, expected);
  EXPECT_LE(r.link_end_slots, 4 * kNodes);  // not 2 (N - 1) x 2 per round, 1400 in all
}

}  // namespace
}  // namespace gcsim::parix
