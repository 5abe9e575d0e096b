// RingBuffer: first-in first-out order across wrap-around and growth, storage that starts at
// nothing and stays at its peak, in-place slots, erase_if, and when a slot lets go of its value.
#include "machine/ring_buffer.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace gcsim::machine {
namespace {

TEST(RingBuffer, KeepsFifoOrderAcrossWrapsAndGrowth) {
  RingBuffer<int, 16> q;
  int pushed = 0, popped = 0;
  for (int round = 0; round < 200; ++round) {
    // Push more than pop for a while (growth while wrapped), then drain partly.
    const int in = round < 100 ? 7 : 3, out = round < 100 ? 5 : 5;
    for (int i = 0; i < in; ++i) q.push_back(pushed++);
    ASSERT_EQ(q.back(), pushed - 1);
    for (int i = 0; i < out && !q.empty(); ++i) {
      ASSERT_EQ(q.front(), popped++);
      q.pop_front();
    }
    ASSERT_EQ(q.size(), static_cast<std::size_t>(pushed - popped));
  }
  EXPECT_EQ(q.capacity() & (q.capacity() - 1), 0u);  // a power of two
  EXPECT_FALSE(q.full());
  while (q.size() < q.capacity()) q.push_back(pushed++);
  EXPECT_TRUE(q.full());
  const std::size_t before = q.capacity();
  q.push_back(pushed++);  // grows
  EXPECT_EQ(q.capacity(), 2 * before);
  EXPECT_FALSE(q.full());
  for (; popped < pushed; ++popped, q.pop_front()) ASSERT_EQ(q.front(), popped);
}

TEST(RingBuffer, HoldsNothingUntilUsedThenItsFirstCapacity) {
  RingBuffer<int, 16> events;
  EXPECT_EQ(events.capacity(), 0u);
  EXPECT_TRUE(events.full());  // so the kernel's fast path sends the first key to the slow one
  events.push_back(1);
  EXPECT_EQ(events.capacity(), 16u);
  RingBuffer<int> queue;
  queue.push_back(1);
  EXPECT_EQ(queue.capacity(), 2u);
}

TEST(RingBuffer, KeepsOrderAndStaysAtItsPeak) {
  RingBuffer<int> q;
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.capacity(), 0u);
  int next_in = 0, next_out = 0;
  for (int round = 0; round < 50; ++round) {  // interleaved pushes and pops, never more than 5 held
    for (int k = 0; k < 3; ++k) q.push_back(next_in++);
    for (int k = 0; k < 2; ++k) {
      ASSERT_EQ(q.front(), next_out++);
      q.pop_front();
    }
    while (q.size() > 4) {
      ASSERT_EQ(q.front(), next_out++);
      q.pop_front();
    }
  }
  while (!q.empty()) {
    ASSERT_EQ(q.front(), next_out++);
    q.pop_front();
  }
  EXPECT_EQ(next_out, next_in);
  EXPECT_EQ(q.capacity(), 8u);  // kept for the next use: its peak of 5, rounded up to a power of two
}

TEST(RingBuffer, AQueueThatNeverEmptiesStaysBounded) {
  RingBuffer<std::unique_ptr<int>> q;
  q.push_back(std::make_unique<int>(0));
  for (int i = 1; i < 100000; ++i) {
    q.push_back(std::make_unique<int>(i));
    ASSERT_EQ(*q.front(), i - 1);
    q.pop_front();
    ASSERT_EQ(q.size(), 1u);
    ASSERT_LE(q.capacity(), 4u);
  }
}

TEST(RingBuffer, AppendFillsTheBackSlotInPlace) {
  RingBuffer<std::vector<int>> q;
  for (int i = 0; i < 5; ++i) q.append().assign(3, i);  // growing on the way: 2, 4, 8 slots
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(q.front(), std::vector<int>(3, i));
    q.pop_front();
  }
  EXPECT_TRUE(q.empty());
}

TEST(RingBuffer, EraseIfKeepsTheOthersInOrder) {
  RingBuffer<int> q;
  for (int i = 0; i < 10; ++i) q.push_back(i);
  q.pop_front();                                  // 1..9
  q.erase_if([](int v) { return v % 3 == 0; });  // drops 3, 6, 9
  std::vector<int> left;
  while (!q.empty()) {
    left.push_back(q.front());
    q.pop_front();
  }
  EXPECT_EQ(left, (std::vector<int>{1, 2, 4, 5, 7, 8}));
  q.push_back(1);
  q.erase_if([](int) { return true; });
  EXPECT_TRUE(q.empty());
  q.push_back(11);  // the slots are reused, from wherever the front stands
  q.push_back(12);
  EXPECT_EQ(q.front(), 11);
  q.pop_front();
  EXPECT_EQ(q.front(), 12);
  EXPECT_EQ(q.capacity(), 16u);
}

TEST(RingBuffer, KeepsOrderWhenItGrowsWrappedAround) {
  RingBuffer<std::unique_ptr<int>> q;
  int next_in = 0, next_out = 0;
  for (int round = 0; round < 20; ++round) {  // the front moves on while the queue deepens
    for (int k = 0; k < 3; ++k) q.push_back(std::make_unique<int>(next_in++));
    ASSERT_EQ(*q.front(), next_out++);
    q.pop_front();
  }
  while (!q.empty()) {
    ASSERT_EQ(*q.front(), next_out++);
    q.front().reset();  // moved out (here: released) by the caller, then dropped
    q.drop_front();
  }
  EXPECT_EQ(next_out, next_in);
  EXPECT_EQ(q.capacity(), 64u);  // the peak of 40, rounded up
}

TEST(RingBuffer, PopFrontReleasesWhatTheSlotHeldDropFrontLeavesIt) {
  auto token = std::make_shared<int>(1);
  RingBuffer<std::shared_ptr<int>> q;
  q.push_back(token);
  q.push_back(token);
  EXPECT_EQ(token.use_count(), 3);
  q.pop_front();
  EXPECT_EQ(token.use_count(), 2);  // at once, not when the slot is next written
  q.drop_front();
  EXPECT_EQ(token.use_count(), 2);  // the caller moves the front out first; the slot still holds it
  q.push_back(nullptr);
  q.push_back(nullptr);  // overwrites the dropped slot
  EXPECT_EQ(token.use_count(), 1);
}

}  // namespace
}  // namespace gcsim::machine
