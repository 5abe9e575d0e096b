// WorkAhead (apps/common/work_ahead.hpp) on its own: every item is what its compute function
// returns, whoever computed it and in whatever order the takers ask; a failure reaches the taker of
// its item, whether a worker or another taker computed it; an item cannot be taken twice. Items
// expected as the run goes (batches of 64-bit ids, as radiosity's cells arrive loop by loop) are
// their computed values too, whether the workers waited for them or not.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "apps/common/work_ahead.hpp"

namespace gcsim::apps {
namespace {

using Ahead = WorkAhead<std::vector<long>>;

std::vector<long> squares_up_to(int item) {
  std::vector<long> v;
  for (long k = 0; k <= item % 500; ++k) v.push_back(k * k + item);  // some work, more for some items
  return v;
}

TEST(WorkAhead, EveryItemIsItsComputedValueInAnyTakingOrder) {
  for (int workers : {1, 3}) {
    const int items = 400;
    std::vector<int> order(items), asked(items);
    for (int i = 0; i < items; ++i) order[std::size_t(i)] = asked[std::size_t(i)] = i;
    std::shuffle(asked.begin(), asked.end(), std::mt19937(7));  // takers ask out of the expected order
    std::vector<Ahead::Compute> computes(std::size_t(workers), squares_up_to);
    Ahead ahead(items, order, computes);
    for (int item : asked) EXPECT_EQ(ahead.take(item, squares_up_to), squares_up_to(item)) << "item " << item;
    EXPECT_LE(ahead.by_workers(), items);
  }
}

TEST(WorkAhead, AFailureReachesTheTakerOfItsItem) {
  const auto failing = [](int item) -> std::vector<long> {
    if (item % 7 == 3) throw std::runtime_error("item " + std::to_string(item));
    return squares_up_to(item);
  };
  const int items = 200;
  std::vector<int> order(items);
  for (int i = 0; i < items; ++i) order[std::size_t(i)] = i;
  Ahead ahead(items, order, {failing, failing});
  for (int item = 0; item < items; ++item) {
    if (item % 7 == 3) EXPECT_THROW(ahead.take(item, failing), std::runtime_error) << "item " << item;
    else EXPECT_EQ(ahead.take(item, failing), squares_up_to(item));
  }
}

TEST(WorkAhead, RefusesWhatCannotBeRight) {
  EXPECT_THROW(Ahead(3, {0, 1, 2}, {}), std::invalid_argument);
  EXPECT_THROW(Ahead(3, {0, 3}, {squares_up_to}), std::invalid_argument);
  Ahead ahead(3, {0, 1, 2}, {squares_up_to});
  ahead.take(1, squares_up_to);
  EXPECT_THROW(ahead.take(1, squares_up_to), std::logic_error);
}

TEST(WorkAhead, ItemsExpectedAsTheRunGoesAreTheirComputedValues) {
  using Open = WorkAhead<std::vector<long>, std::int64_t>;
  const auto compute = [](std::int64_t item) { return squares_up_to(int(item % 1000)); };
  for (int workers : {1, 3}) {
    Open ahead(std::vector<Open::Compute>(std::size_t(workers), compute));
    for (std::int64_t batch = 0; batch < 20; ++batch) {
      const std::int64_t first = batch * 5'000'000'000LL;  // ids beyond int
      std::vector<std::int64_t> items;
      for (std::int64_t i = 0; i < 50; ++i) items.push_back(first + i);
      ahead.expect(items);
      ahead.expect({first});  // expected again: keeps its place, not a second slot
      for (std::int64_t i = 49; i >= 0; --i)  // taken against the expected order
        EXPECT_EQ(ahead.take(first + i, compute), compute(first + i)) << "batch " << batch << ", item " << i;
      EXPECT_THROW(ahead.take(first, compute), std::logic_error);  // its slot is freed once taken
    }
    EXPECT_LE(ahead.by_workers(), 20 * 50);
  }
}

}  // namespace
}  // namespace gcsim::apps
