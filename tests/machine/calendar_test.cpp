#include "machine/calendar.hpp"

#include <gtest/gtest.h>

#include <array>

namespace gcsim::machine {
namespace {

TEST(Calendar, TakesTheEarliestGapThatFits) {
  Calendar c;
  EXPECT_EQ(c.take(10, 5), 10);   // [10, 15)
  EXPECT_EQ(c.take(20, 5), 20);   // [20, 25)
  EXPECT_EQ(c.take(0, 5), 0);     // fits before [10, 15)
  EXPECT_EQ(c.take(12, 5), 15);   // 12 overlaps [10, 15); [15, 20) is exactly long enough
  EXPECT_EQ(c.take(12, 1), 25);   // now every gap after 12 is taken up to 25
}

TEST(Calendar, ExactFitBetweenReservations) {
  Calendar c;
  c.take(0, 10);
  c.take(15, 10);
  EXPECT_EQ(c.earliest(0, 5), 10);
  EXPECT_EQ(c.earliest(0, 6), 25);
}

TEST(Calendar, ForgetsOnlyWhatEnded) {
  Calendar c;
  c.take(0, 10);
  c.take(10, 10);
  c.forget_before(10);
  EXPECT_EQ(c.size(), 1u);
  EXPECT_EQ(c.earliest(10, 1), 20);
}

TEST(Calendar, CommonGapOfSeveralCalendars) {
  Calendar a, b;
  a.take(0, 10);   // a busy [0, 10)
  b.take(12, 10);  // b busy [12, 22)
  std::array<Calendar*, 2> both{&a, &b};
  EXPECT_EQ(Calendar::earliest_common(both, 0, 2), 10);  // [10, 12) free in both
  EXPECT_EQ(Calendar::earliest_common(both, 0, 3), 22);
}

}  // namespace
}  // namespace gcsim::machine
