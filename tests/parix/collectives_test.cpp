#include "parix/collectives.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::parix {
namespace {

using test_support::on_nodes;

struct Case {
  int nodes;
  BcastAlgo algo;
  bool per_message;
};

std::vector<Case> all_cases() {
  std::vector<Case> cs;
  for (int n : {1, 2, 3, 4, 5, 7, 8, 9, 16}) {
    for (BcastAlgo a : {BcastAlgo::sequential, BcastAlgo::tree}) {
      for (bool pm : {true, false}) cs.push_back({n, a, pm});
    }
  }
  return cs;
}

std::string name(const Case& c) {
  return std::to_string(c.nodes) + (c.algo == BcastAlgo::tree ? " tree" : " sequential") +
         (c.per_message ? " per-message" : " persistent");
}

Bytes tagged(int id, int len) {
  Bytes b(static_cast<std::size_t>(len));
  for (int i = 0; i < len; ++i) b[i] = std::byte(id * 31 + i);
  return b;
}

TEST(Collectives, TreeShapeCoversEveryProcessorOnce) {
  for (int n = 1; n < 40; ++n) {
    for (int root = 0; root < n; root += 3) {
      std::vector<int> parents_of(n, 0);
      for (int id = 0; id < n; ++id) {
        for (int c : tree_children(id, root, n)) {
          ++parents_of[c];
          EXPECT_EQ(tree_parent(c, root, n), id);
        }
      }
      for (int id = 0; id < n; ++id) EXPECT_EQ(parents_of[id], id == root ? 0 : 1);
      EXPECT_EQ(tree_parent(root, root, n), -1);
    }
  }
}

TEST(Collectives, BroadcastDeliversTheRootsData) {
  for (const Case& c : all_cases()) {
    const int root = c.nodes / 2;
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      CollectiveOptions o{c.algo, c.per_message};
      Bytes got = broadcast(p, root, p.id() == root ? tagged(root, 300) : Bytes{}, o);
      EXPECT_EQ(got, tagged(root, 300)) << name(c);
    });
  }
}

TEST(Collectives, GatherCollectsEveryContributionAtTheRoot) {
  for (const Case& c : all_cases()) {
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      CollectiveOptions o{c.algo, c.per_message};
      const int root = c.nodes - 1;
      auto all = gather(p, root, tagged(p.id(), p.id() + 1), o);
      if (p.id() == root) {
        ASSERT_EQ(static_cast<int>(all.size()), c.nodes) << name(c);
        for (int q = 0; q < c.nodes; ++q) EXPECT_EQ(all[q], tagged(q, q + 1)) << name(c);
      } else {
        EXPECT_TRUE(all.empty());
      }
    });
  }
}

TEST(Collectives, AllgatherGivesEveryoneEverything) {
  for (const Case& c : all_cases()) {
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      CollectiveOptions o{c.algo, c.per_message};
      auto all = allgather(p, tagged(p.id(), 2 * p.id()), o);
      ASSERT_EQ(static_cast<int>(all.size()), c.nodes);
      for (int q = 0; q < c.nodes; ++q) EXPECT_EQ(all[q], tagged(q, 2 * q)) << name(c);
    });
  }
}

// The views variant makes the same exchange (same simulated time) and shows the same parts.
TEST(Collectives, AllgatherViewsAreTheAllgathersParts) {
  for (const Case& c : all_cases()) {
    SimTime copied = 0, viewed = 0;
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      auto all = allgather(p, tagged(p.id(), 2 * p.id()), {c.algo, c.per_message});
      if (p.id() == 0) copied = p.now();
    });
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      const GatheredBytes g = allgather_views(p, tagged(p.id(), 2 * p.id()), {c.algo, c.per_message});
      ASSERT_EQ(static_cast<int>(g.parts.size()), c.nodes);
      for (int q = 0; q < c.nodes; ++q)
        EXPECT_EQ(Bytes(g.parts[q].begin(), g.parts[q].end()), tagged(q, 2 * q)) << name(c);
      if (p.id() == 0) viewed = p.now();
    });
    EXPECT_EQ(copied, viewed) << name(c);
  }
}

TEST(Collectives, ReduceAndAllreduceSum) {
  for (const Case& c : all_cases()) {
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      CollectiveOptions o{c.algo, c.per_message};
      const long expected = static_cast<long>(c.nodes) * (c.nodes + 1) / 2;
      EXPECT_EQ(allreduce_sum<long>(p, p.id() + 1, o), expected) << name(c);
    });
  }
}

TEST(Collectives, TypedAllgather) {
  run_simulated(on_nodes(5), [](Processor& p) {
    const std::vector<float> mine(static_cast<std::size_t>(p.id()), float(p.id()));
    auto all = allgather_vectors<float>(p, mine);
    for (int q = 0; q < 5; ++q) EXPECT_EQ(all[q], std::vector<float>(static_cast<std::size_t>(q), float(q)));
  });
}

TEST(Collectives, ConcatenatedAllgatherIsThePartsInProcessorOrder) {
  run_simulated(on_nodes(5), [](Processor& p) {
    const std::vector<float> mine(static_cast<std::size_t>(p.id()), float(p.id()));
    std::vector<float> expected;
    for (int q = 0; q < 5; ++q) expected.insert(expected.end(), std::size_t(q), float(q));
    EXPECT_EQ(allgather_concatenated<float>(p, mine), expected);
  });
}

// same_as compares the parts, in order, with a whole without concatenating them: equal only for the
// same bytes in the same places, whatever the parts' sizes (empty ones included).
TEST(Collectives, GatheredPartsAreTheSameAsTheirConcatenationAndNothingElse) {
  run_simulated(on_nodes(5), [](Processor& p) {
    const GatheredBytes g = allgather_views(p, tagged(p.id(), 3 * (p.id() % 3)));  // parts of 0, 3, 6, 0, 3 bytes
    const std::vector<std::byte> whole = concatenated<std::byte>(g);
    ASSERT_EQ(g.size(), 12u);
    ASSERT_EQ(whole.size(), 12u);
    EXPECT_TRUE(g.same_as(whole));
    std::vector<std::byte> changed = whole;
    changed[7] ^= std::byte{1};  // inside the third part
    EXPECT_FALSE(g.same_as(changed));
    EXPECT_FALSE(g.same_as(std::span(whole).first(11)));  // shorter
    std::vector<std::byte> longer = whole;
    longer.push_back(std::byte{0});
    EXPECT_FALSE(g.same_as(longer));
    EXPECT_FALSE(g.same_as({}));
    std::vector<std::byte> swapped(whole.begin() + 3, whole.end());  // parts 2 and 3 moved before part 1
    swapped.insert(swapped.end(), whole.begin(), whole.begin() + 3);
    EXPECT_FALSE(g.same_as(swapped));
  });
}

TEST(Collectives, BarrierWaitsForTheSlowest) {
  for (const Case& c : all_cases()) {
    std::vector<SimTime> after(c.nodes);
    run_simulated(on_nodes(c.nodes), [&](Processor& p) {
      p.compute("cycle", 80'000 * (p.id() + 1));  // processor i works i+1 ms
      barrier(p, {c.algo, c.per_message});
      after[p.id()] = p.now();
    });
    for (SimTime t : after) EXPECT_GE(t, machine::kMillisecond * c.nodes) << name(c);
  }
}

}  // namespace
}  // namespace gcsim::parix
