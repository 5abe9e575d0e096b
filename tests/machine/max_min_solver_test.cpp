#include "machine/max_min_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

namespace gcsim::machine {
namespace {

// Progressive filling from scratch over all flows, the way the flow model solved before the
// solver replayed its levels: the reference the incremental solver must match bit for bit.
std::map<int, double> full_solve(const std::map<int, std::vector<int>>& routes, int channels, double capacity) {
  std::vector<std::vector<int>> on(static_cast<std::size_t>(channels));
  for (const auto& [slot, route] : routes)
    for (int ch : route) on[static_cast<std::size_t>(ch)].push_back(slot);
  std::vector<double> left(static_cast<std::size_t>(channels), capacity);
  std::vector<int> unassigned(static_cast<std::size_t>(channels));
  for (std::size_t c = 0; c < on.size(); ++c) unassigned[c] = static_cast<int>(on[c].size());
  std::map<int, double> rate;
  for (;;) {
    int best = -1;
    double best_share = 0;
    for (int ch = 0; ch < channels; ++ch) {
      const auto c = static_cast<std::size_t>(ch);
      if (on[c].size() < 2 || unassigned[c] == 0) continue;
      const double share = left[c] / unassigned[c];
      if (best < 0 || share < best_share) best = ch, best_share = share;  // lowest channel on a tie
    }
    if (best < 0) break;
    for (int slot : on[static_cast<std::size_t>(best)]) {
      if (rate.count(slot)) continue;
      rate[slot] = best_share;
      for (int ch : routes.at(slot)) {
        left[static_cast<std::size_t>(ch)] -= best_share;
        --unassigned[static_cast<std::size_t>(ch)];
      }
    }
  }
  for (const auto& [slot, route] : routes)
    if (!rate.count(slot)) rate[slot] = capacity;
  return rate;
}

// Starts and finishes random flows over random channel sets (routes of a few channels out of a
// few dozen, so that levels tie, cascade and split components) and checks every rate and the
// changed list against a solve from scratch after each change.
void check_random_run(unsigned seed, int channels, int max_route, int steps, double capacity = 4 * 35e6 / 16) {
  MaxMinSolver solver(channels, capacity);
  std::mt19937 rng(seed);
  std::map<int, std::vector<int>> routes;  // started flows by slot
  std::map<int, double> before;
  for (int step = 0; step < steps; ++step) {
    const bool add = routes.empty() || (routes.size() < 40 && rng() % 100 < 55);
    int fresh = -1;
    if (add) {
      const int slot = solver.open();
      std::vector<int>& route = solver.route(slot);
      // max_route < 0: short routes (small groups) and now and then a long one bridging groups.
      const int len = max_route > 0 ? 1 + static_cast<int>(rng() % static_cast<unsigned>(max_route))
                      : rng() % 6 == 0 ? 1 + static_cast<int>(rng() % static_cast<unsigned>(-max_route))
                                       : 1 + static_cast<int>(rng() % 2);
      while (static_cast<int>(route.size()) < len) {
        const int ch = static_cast<int>(rng() % static_cast<unsigned>(channels));
        if (std::find(route.begin(), route.end(), ch) == route.end()) route.push_back(ch);
      }
      routes[slot] = route;
      solver.start(slot);
      fresh = slot;
    } else {
      auto it = routes.begin();
      std::advance(it, static_cast<long>(rng() % routes.size()));
      const int slot = it->first;
      routes.erase(it);
      before.erase(slot);
      solver.finish(slot);
    }
    const std::map<int, double> expected = full_solve(routes, channels, capacity);
    std::vector<int> expected_changed;
    for (const auto& [slot, r] : expected) {
      ASSERT_EQ(solver.rate(slot), r) << "seed " << seed << " step " << step << " slot " << slot;
      if (slot == fresh || before.at(slot) != r) expected_changed.push_back(slot);
    }
    std::vector<int> changed = solver.changed();
    std::sort(changed.begin(), changed.end());
    ASSERT_EQ(changed, expected_changed) << "seed " << seed << " step " << step;
    ASSERT_EQ(solver.active(), routes.size());
    before = expected;
  }
}

TEST(MaxMinSolver, MatchesAFullSolveBitForBitAfterEveryChange) {
  for (unsigned seed = 1; seed <= 40; ++seed) check_random_run(seed, 24, 6, 300);
  for (unsigned seed = 41; seed <= 60; ++seed) check_random_run(seed, 24, 6, 300, 1e7 / 3);
}

TEST(MaxMinSolver, MatchesAFullSolveWithLongRoutesOverManyChannels) {
  for (unsigned seed = 100; seed <= 110; ++seed) check_random_run(seed, 200, 30, 400);
}

// Short routes over many channels: many groups, which starts join now and then (their levels
// interleaved) and which stay joined when the flows linking them end.
TEST(MaxMinSolver, MatchesAFullSolveAcrossManyGroups) {
  for (unsigned seed = 200; seed <= 215; ++seed) check_random_run(seed, 300, 3, 500);
  // A capacity no share of which is exact, so that any change in the order of subtractions shows.
  for (unsigned seed = 300; seed <= 315; ++seed) check_random_run(seed, 300, 3, 500, 1e7 / 3);
  for (unsigned seed = 400; seed <= 460; ++seed) check_random_run(seed, 60, -12, 300, 1e7 / 3);
}

// The rates depend on the set of flows only: started in opposite orders (so that the levels are
// built through different cascades), the same flows get the same rates, bit for bit.
TEST(MaxMinSolver, RatesDoNotDependOnTheOrderOfStarts) {
  for (unsigned seed = 7; seed <= 17; ++seed) {
    std::mt19937 rng(seed);
    std::vector<std::vector<int>> routes(30);
    for (auto& route : routes) {
      const int len = 1 + static_cast<int>(rng() % 8);
      while (static_cast<int>(route.size()) < len) {
        const int ch = static_cast<int>(rng() % 40);
        if (std::find(route.begin(), route.end(), ch) == route.end()) route.push_back(ch);
      }
    }
    MaxMinSolver forward(40, 1e7), backward(40, 1e7);
    std::vector<int> fwd(routes.size()), bwd(routes.size());
    for (std::size_t i = 0; i < routes.size(); ++i) {
      fwd[i] = forward.open();
      forward.route(fwd[i]) = routes[i];
      forward.start(fwd[i]);
    }
    for (std::size_t i = routes.size(); i-- > 0;) {
      bwd[i] = backward.open();
      backward.route(bwd[i]) = routes[i];
      backward.start(bwd[i]);
    }
    for (std::size_t i = 0; i < routes.size(); ++i) EXPECT_EQ(forward.rate(fwd[i]), backward.rate(bwd[i])) << seed;
  }
}

// Channel 0 carries A, B and C, channel 1 carries C and D, channel 2 only D: channel 0 saturates
// first at c/3 each, which leaves D 2c/3 on channel 1. When A ends, channel 0 offers c/2 to B and
// C, channel 1 then gives D c/2 as well: all three change, and D alone on its channels after C
// ends gets the whole capacity.
TEST(MaxMinSolver, HandComputedCascade) {
  const double c = 3.0;
  MaxMinSolver s(3, c);
  auto start = [&](std::vector<int> route) {
    const int slot = s.open();
    s.route(slot) = std::move(route);
    s.start(slot);
    return slot;
  };
  const int a = start({0}), b = start({0}), cc = start({0, 1}), d = start({1, 2});
  EXPECT_EQ(s.rate(a), 1.0);
  EXPECT_EQ(s.rate(b), 1.0);
  EXPECT_EQ(s.rate(cc), 1.0);
  EXPECT_EQ(s.rate(d), 2.0);
  s.finish(a);
  EXPECT_EQ(s.rate(b), 1.5);
  EXPECT_EQ(s.rate(cc), 1.5);
  EXPECT_EQ(s.rate(d), 1.5);
  std::vector<int> changed = s.changed();
  std::sort(changed.begin(), changed.end());
  EXPECT_EQ(changed, (std::vector<int>{b, cc, d}));
  s.finish(cc);
  EXPECT_EQ(s.rate(b), 3.0);
  EXPECT_EQ(s.rate(d), 3.0);
  EXPECT_EQ(s.active(), 2u);
}

// A change that touches no shared channel of the others leaves their rates and levels alone.
TEST(MaxMinSolver, DisjointFlowChangesNothingElse) {
  MaxMinSolver s(6, 1.0);
  const int x = s.open();
  s.route(x) = {0, 1};
  s.start(x);
  const int y = s.open();
  s.route(y) = {1, 2};
  s.start(y);
  const int z = s.open();
  s.route(z) = {4, 5};
  s.start(z);
  EXPECT_EQ(s.changed(), (std::vector<int>{z}));
  EXPECT_EQ(s.rate(x), 0.5);
  EXPECT_EQ(s.rate(z), 1.0);
  s.finish(z);
  EXPECT_TRUE(s.changed().empty());
}

// Two pairs on channels 0 and 5 are two groups; a flow over both channels joins them. After it
// ends the group is split again once it has seen as many ends as it has flows (four).
TEST(MaxMinSolver, GroupsJoinThroughABridgeAndSplitAfterIt) {
  MaxMinSolver s(10, 1.0);
  auto start = [&](std::vector<int> route) {
    const int slot = s.open();
    s.route(slot) = std::move(route);
    s.start(slot);
    return slot;
  };
  const int x = start({0});
  start({0});
  const int y = start({5});
  start({5});
  EXPECT_EQ(s.groups(), 2u);
  const int bridge = start({0, 5});
  EXPECT_EQ(s.groups(), 1u);
  EXPECT_EQ(s.rate(x), 1.0 / 3);
  s.finish(bridge);
  EXPECT_EQ(s.groups(), 1u);
  for (int end = 2; end <= 4; ++end) {
    s.finish(start({0}));
    EXPECT_EQ(s.groups(), end < 4 ? 1u : 2u) << end;
  }
  EXPECT_EQ(s.rate(x), 0.5);
  EXPECT_EQ(s.rate(y), 0.5);
  // The split groups still solve like one: a new bridge gets a third on channel 0 (the lower of two
  // equal shares, filled first), which leaves the two others on channel 5 (1 - 1/3) / 2 each.
  start({0, 5});
  EXPECT_EQ(s.rate(x), 1.0 / 3);
  EXPECT_EQ(s.rate(y), (1.0 - 1.0 / 3) / 2);
}

}  // namespace
}  // namespace gcsim::machine
