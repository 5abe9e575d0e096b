#include "machine/kernel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <utility>
#include <memory>
#include <vector>

namespace gcsim::machine {
namespace {

// The events ran (by id) in the order a plain sort of every (time, id) gives: time, then
// scheduling order, as ids are given in scheduling order.
void expect_ran_in_key_order(const std::vector<int>& ran, std::vector<std::pair<SimTime, int>> scheduled) {
  std::sort(scheduled.begin(), scheduled.end());
  ASSERT_EQ(ran.size(), scheduled.size());
  for (std::size_t i = 0; i < ran.size(); ++i) ASSERT_EQ(ran[i], scheduled[i].second) << "at position " << i;
}

TEST(Kernel, RunsEventsInTimeOrder) {
  Kernel k;
  std::vector<int> order;
  k.at(30, [&] { order.push_back(3); });
  k.at(10, [&] { order.push_back(1); });
  k.at(20, [&] { order.push_back(2); });
  k.run();
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(k.now(), 30);
  EXPECT_EQ(k.events_processed(), 3u);
}

TEST(Kernel, BreaksTiesBySchedulingOrder) {
  Kernel k;
  std::vector<int> order;
  for (int i = 0; i < 100; ++i) k.at(5, [&, i] { order.push_back(i); });
  k.run();
  ASSERT_EQ(order.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(order[i], i);
}

TEST(Kernel, EventsScheduledDuringAnEventAtTheSameTimeRunAfterIt) {
  Kernel k;
  std::vector<int> order;
  k.at(7, [&] {
    order.push_back(1);
    k.after(0, [&] { order.push_back(3); });
  });
  k.at(7, [&] { order.push_back(2); });
  k.run();
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
}

TEST(Kernel, RejectsEventsInThePast) {
  Kernel k;
  k.at(100, [] {});
  k.step();
  EXPECT_THROW(k.at(99, [] {}), std::logic_error);
}

TEST(Kernel, StepOnEmptyQueueReturnsFalse) {
  Kernel k;
  EXPECT_FALSE(k.step());
  EXPECT_TRUE(k.idle());
}

TEST(Kernel, KeepsPicosecondResolutionOverLongRuns) {
  // A simulated month in picoseconds is far below int64's range, and one picosecond still counts.
  Kernel k;
  const SimTime month = 31LL * 24 * 3600 * kSecond;
  SimTime seen = 0;
  k.at(month, [&] { k.after(1, [&] { seen = k.now(); }); });
  k.run();
  EXPECT_EQ(seen, month + 1);
  EXPECT_LT(3 * month, std::numeric_limits<SimTime>::max());  // 106 days fit
}

// Actions of every kind -- small and trivially movable, owning (a shared_ptr), too big to store
// inline -- run once each, in (time, order of scheduling) order, and are destroyed exactly once,
// also when they reschedule while the slot pool grows under them.
TEST(Kernel, ActionsOfEverySizeRunOnceAndAreReleased) {
  Kernel k;
  auto token = std::make_shared<int>(0);
  std::vector<int> order;
  struct Big {
    char pad[200];
  };
  for (int i = 0; i < 3000; ++i) {
    const SimTime t = (i * 7919) % 101;
    if (i % 3 == 0) k.at(t, [&order, i] { order.push_back(i); });
    else if (i % 3 == 1) k.at(t, [&order, i, token] { order.push_back(i); });
    else k.at(t, [&order, i, big = Big{}] { order.push_back(i + big.pad[0]); });
  }
  EXPECT_EQ(token.use_count(), 1 + 1000);
  // An action that schedules more while it runs (the pool grows by chunks meanwhile).
  int chained = 0;
  std::function<void()> chain = [&] {
    if (++chained < 5000) k.after(0, [&] { chain(); });
  };
  k.at(200, [&] { chain(); });
  k.run();
  EXPECT_EQ(chained, 5000);
  EXPECT_EQ(token.use_count(), 1);  // every copy destroyed after running
  ASSERT_EQ(order.size(), 3000u);
  std::vector<int> expected(3000);
  for (int i = 0; i < 3000; ++i) expected[i] = i;
  std::stable_sort(expected.begin(), expected.end(),
                   [](int a, int b) { return (a * 7919) % 101 < (b * 7919) % 101; });
  EXPECT_EQ(order, expected);
}

// Events scheduled from within events, in long in-order stretches (a steady message flow: the
// kernel's FIFO run) broken by earlier ones (its heap), still run in (time, scheduling order),
// the order a plain sort of every (time, sequence) gives.
TEST(Kernel, MixedInOrderAndOutOfOrderEventsRunInTimeThenSchedulingOrder) {
  Kernel k;
  std::vector<std::pair<SimTime, int>> scheduled;  // (time, sequence) of every event
  std::vector<int> ran;
  std::uint32_t rng = 12345;
  auto next = [&rng] { return rng = rng * 1664525u + 1013904223u, rng >> 8; };
  std::function<void(int)> event = [&](int id) {
    ran.push_back(id);
    if (scheduled.size() >= 20000) return;
    const int children = 1 + static_cast<int>(next() % 2);
    for (int c = 0; c < children && scheduled.size() < 20000; ++c) {
      // Mostly the same delay (in order), sometimes shorter or zero (out of order, or a tie).
      const std::uint32_t r = next() % 10;
      const SimTime delay = r < 7 ? 1000 : r < 9 ? static_cast<SimTime>(next() % 1000) : 0;
      const int child = static_cast<int>(scheduled.size());
      scheduled.push_back({k.now() + delay, child});
      k.after(delay, [&event, child] { event(child); });
    }
  };
  for (int i = 0; i < 64; ++i) {
    scheduled.push_back({static_cast<SimTime>(next() % 500), i});
    k.at(scheduled.back().first, [&event, i] { event(i); });
  }
  k.run();
  expect_ran_in_key_order(ran, scheduled);
  EXPECT_TRUE(k.idle());
  EXPECT_EQ(k.pending(), 0u);
}

// Several steady flows, each with its own delay (an MPI message's sender overhead, transfer and
// receiver overhead), interleaved from many sources and broken now and then by a delay of no
// flow: more flows than the kernel has runs, so keys go to runs and to the heap, and still run
// in the order a plain sort of every (time, sequence) gives.
TEST(Kernel, InterleavedFlowsOfSeveralDelaysRunInTimeThenSchedulingOrder) {
  Kernel k;
  std::vector<std::pair<SimTime, int>> scheduled;
  std::vector<int> ran;
  std::uint32_t rng = 777;
  auto next = [&rng] { return rng = rng * 1664525u + 1013904223u, rng >> 8; };
  const SimTime flows[] = {40, 1000, 40, 390, 5000};
  std::function<void(int)> event = [&](int id) {
    ran.push_back(id);
    if (scheduled.size() >= 30000) return;
    const std::uint32_t r = next() % 20;
    const SimTime delay = r < 18 ? flows[next() % 5] : static_cast<SimTime>(next() % 6000);
    const int child = static_cast<int>(scheduled.size());
    scheduled.push_back({k.now() + delay, child});
    k.after(delay, [&event, child] { event(child); });
  };
  for (int i = 0; i < 128; ++i) {
    scheduled.push_back({static_cast<SimTime>(next() % 2000), i});
    k.at(scheduled.back().first, [&event, i] { event(i); });
  }
  k.run();
  expect_ran_in_key_order(ran, scheduled);
  EXPECT_TRUE(k.idle());
  EXPECT_EQ(k.pending(), 0u);
}

// The kernel compares a new key with the time of the last key its in-order run took, not with
// the run's back: after the run empties (its keys run, or moved to the heap), keys between now
// and the heap's still go in time order.
TEST(Kernel, KeysAfterTheInOrderRunEmptiedRunInTimeOrder) {
  Kernel k;
  std::vector<int> order;
  k.at(100, [&] { order.push_back(100); });
  k.at(50, [&] { order.push_back(50); });  // earlier: another run
  ASSERT_TRUE(k.step());                   // 50; its run is empty
  EXPECT_EQ(k.now(), 50);
  k.at(60, [&] { order.push_back(60); });
  k.at(55, [&] { order.push_back(55); });  // earlier than the run's last (60)
  k.at(55, [&] { order.push_back(56); });  // a tie: after the first 55
  EXPECT_THROW(k.at(49, [] {}), std::logic_error);
  k.run();
  EXPECT_EQ(order, (std::vector<int>{50, 55, 56, 60, 100}));
}

TEST(KernelAction, MovesLeaveTheSourceEmpty) {
  auto token = std::make_shared<int>(7);
  int seen = 0;
  KernelAction a = [&seen, token] { seen = *token; };
  KernelAction b = std::move(a);
  EXPECT_FALSE(a);  // NOLINT(bugprone-use-after-move): moved-from is empty by contract
  EXPECT_TRUE(b);
  b();
  EXPECT_EQ(seen, 7);
  b.reset();
  EXPECT_EQ(token.use_count(), 1);
  // fill: into an empty action, both for an owning callable (moved by its manager) and a plain one.
  KernelAction c;
  c.fill(KernelAction([&seen, token] { seen = *token + 1; }));
  EXPECT_EQ(token.use_count(), 2);
  c();
  EXPECT_EQ(seen, 8);
  KernelAction d;
  d.fill(KernelAction([&seen] { seen = 9; }));
  d();
  EXPECT_EQ(seen, 9);
  c.reset();
  EXPECT_EQ(token.use_count(), 1);
}

TEST(SimTime, ConversionsRoundCostsUp) {
  EXPECT_EQ(from_seconds(1e-12), 1);
  EXPECT_EQ(from_seconds(0.4e-12), 1);  // a non-zero cost never becomes free
  EXPECT_EQ(from_seconds(0), 0);
  EXPECT_DOUBLE_EQ(to_seconds(kSecond), 1.0);
  EXPECT_DOUBLE_EQ(to_milliseconds(3 * kMillisecond), 3.0);
}

}  // namespace
}  // namespace gcsim::machine
