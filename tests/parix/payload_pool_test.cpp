// The payload pool on its own (parix/sim/payload_pool.hpp): storage given back is reused by a later
// copy that fits, a copy never gets storage that is too small or far too large, and the pool keeps
// no more than its limit.
#include "parix/sim/payload_pool.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace gcsim::parix::detail {
namespace {

Bytes filled(std::size_t n, std::byte v = std::byte{7}) { return Bytes(n, v); }

TEST(PayloadPool, ACopyReusesStorageGivenBack) {
  PayloadPool pool;
  Bytes first = pool.copy(filled(64));
  const std::byte* storage = first.data();
  pool.give(std::move(first));
  EXPECT_TRUE(first.empty());  // NOLINT(bugprone-use-after-move): give leaves it empty
  EXPECT_EQ(pool.kept(), 1u);
  EXPECT_EQ(pool.kept_bytes(), 64u);
  const Bytes second = pool.copy(filled(64, std::byte{9}));
  EXPECT_EQ(second.data(), storage);
  EXPECT_EQ(second, filled(64, std::byte{9}));
  EXPECT_EQ(pool.kept(), 0u);
}

// copy_into fills a message's slot in place: with its own storage when that fits, else with recycled
// storage, the slot's own coming back to the pool.
TEST(PayloadPool, ACopyIntoReusesStorageInPlace) {
  PayloadPool pool;
  Bytes given = filled(64);
  const std::byte* storage = given.data();
  pool.give(std::move(given));
  Bytes slot = filled(3, std::byte{5});  // too small: back to the pool, its contents dropped
  pool.copy_into(slot, filled(64, std::byte{9}));
  EXPECT_EQ(slot.data(), storage);
  EXPECT_EQ(slot, filled(64, std::byte{9}));
  EXPECT_EQ(pool.kept(), 1u);
  EXPECT_EQ(pool.kept_bytes(), 3u);
  // The slot's own storage fits a shorter message (a slot keeps a receiver's old vector).
  pool.copy_into(slot, filled(40, std::byte{4}));
  EXPECT_EQ(slot.data(), storage);
  EXPECT_EQ(slot, filled(40, std::byte{4}));
  EXPECT_EQ(pool.kept(), 1u);
  // An empty message carries no storage: the slot's comes back here.
  pool.copy_into(slot, {});
  EXPECT_TRUE(slot.empty());
  EXPECT_EQ(slot.capacity(), 0u);
  EXPECT_EQ(pool.kept(), 2u);
  EXPECT_EQ(pool.kept_bytes(), 67u);
}

TEST(PayloadPool, ACopyGetsStorageThatFits) {
  PayloadPool pool;
  Bytes small;
  small.reserve(100);  // class 64..127
  const std::byte* small_storage = small.data();
  pool.give(std::move(small));
  const Bytes bigger = pool.copy(filled(120));  // same class, but 100 bytes do not fit
  EXPECT_NE(bigger.data(), small_storage);
  EXPECT_GE(bigger.capacity(), 120u);
  EXPECT_EQ(bigger.size(), 120u);
  const Bytes fits = pool.copy(filled(90));  // the 100-byte storage does
  EXPECT_EQ(fits.data(), small_storage);
}

TEST(PayloadPool, ASmallMessageDoesNotTakeAFarLargerBuffer) {
  PayloadPool pool;
  Bytes large;
  large.reserve(4096);
  const std::byte* large_storage = large.data();
  pool.give(std::move(large));
  const Bytes tiny = pool.copy(filled(8));
  EXPECT_NE(tiny.data(), large_storage);
  EXPECT_EQ(pool.kept(), 1u);  // still there for a message it suits
  const Bytes suits = pool.copy(filled(1500));  // 1500..4095: at most two classes below
  EXPECT_EQ(suits.data(), large_storage);
}

TEST(PayloadPool, ZeroLengthMessagesHoldNoStorage) {
  PayloadPool pool;
  const Bytes empty = pool.copy({});
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.capacity(), 0u);
  pool.give(Bytes{});
  EXPECT_EQ(pool.kept(), 0u);
}

TEST(PayloadPool, KeepsNoMoreThanItsLimit) {
  PayloadPool pool;
  const std::size_t chunk = PayloadPool::kMaxKeptBytes / 4;
  for (int i = 0; i < 6; ++i) {
    Bytes b;
    b.reserve(chunk);
    pool.give(std::move(b));
  }
  EXPECT_EQ(pool.kept(), 4u);
  EXPECT_EQ(pool.kept_bytes(), PayloadPool::kMaxKeptBytes);
}

}  // namespace
}  // namespace gcsim::parix::detail
