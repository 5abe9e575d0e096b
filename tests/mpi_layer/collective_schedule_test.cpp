// Each algorithm's schedule on the in-memory channel equals its textbook formula: messages,
// rounds (communication steps under the full-duplex one-port model, in_memory_channel.hpp)
// and, where the formula is simple, bytes moved and bytes reduced. n ranks, L = ceil(log2 n),
// p the largest power of two <= n, rem = n - p.
#include <bit>

#include "tests/mpi_layer/collective_test_support.hpp"

namespace gcsim::mpi_layer::testing {
namespace {

using A = Algorithm;

int ceil_log2(int n) { return n <= 1 ? 0 : std::bit_width(static_cast<unsigned>(n - 1)); }
int floor_pow2(int n) { return static_cast<int>(std::bit_floor(static_cast<unsigned>(n))); }
std::size_t sz(int v) { return static_cast<std::size_t>(v); }

// The schedule with buffered sends; with synchronous ones (rendezvous) it must run too, without
// deadlock, to the same figures.
template <class Body>
ScheduleStats stats_of(int n, Body body) {
  ScheduleStats buffered, synchronous;
  outputs_of(n, [&](const CollectiveCall& call, int r) { body(call, r); return Bytes{}; }, &buffered,
             SendMode::Buffered);
  outputs_of(n, [&](const CollectiveCall& call, int r) { body(call, r); return Bytes{}; }, &synchronous,
             SendMode::Synchronous);
  EXPECT_EQ(buffered, synchronous) << n << " ranks: the schedule changed with synchronous sends";
  return buffered;
}

const OpCase& sum_int() {
  static const OpCase op = op_cases().front();
  return op;
}

ScheduleStats allreduce_stats(int n, A a, std::size_t count, const OpCase& op = sum_int()) {
  return stats_of(n, [&](const CollectiveCall& call, int r) {
    Bytes result(count * op.reduction.element_size);
    allreduce(call, op.data(r, count), result, count, op.reduction, a);
  });
}

TEST(MpiCollectiveSchedule, DisseminationBarrierSendsNTimesCeilLog2NEmptyMessages) {
  for (int n : rank_counts) {
    const ScheduleStats s = stats_of(n, [](const CollectiveCall& call, int) { barrier(call); });
    EXPECT_EQ(s.messages, sz(n * ceil_log2(n))) << n;
    EXPECT_EQ(s.rounds, ceil_log2(n)) << n;
    EXPECT_EQ(s.bytes, 0u);
  }
}

TEST(MpiCollectiveSchedule, BinomialBcastIsNMinusOneMessagesInCeilLog2NRounds) {
  for (int n : rank_counts)
    for (int root = 0; root < n; ++root) {
      const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int) {
        Bytes b(64);
        bcast(call, b, root, A::Binomial);
      });
      EXPECT_EQ(s.messages, sz(n - 1)) << n;
      EXPECT_EQ(s.rounds, ceil_log2(n)) << n;
      EXPECT_EQ(s.bytes, sz(n - 1) * 64);
    }
}

// Scatter: n-1 messages moving (B/n)(n/2)log2 n bytes on a power of two; ring allgather: n(n-1)
// messages moving (n-1)B.
TEST(MpiCollectiveSchedule, ScatterAllgatherBcastMovesVanDeGeijnsVolume) {
  for (int n : rank_counts) {
    const std::size_t bytes = sz(16 * n);
    const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int) {
      Bytes b(bytes);
      bcast(call, b, 0, A::ScatterAllgather);
    });
    if (n == 1) continue;
    EXPECT_EQ(s.messages, sz(n - 1) + sz(n * (n - 1))) << n;
    if ((n & (n - 1)) == 0) {
      EXPECT_EQ(s.bytes, 16 * sz(n / 2 * ceil_log2(n)) + sz(n - 1) * bytes) << n;
    }
    EXPECT_EQ(s.rounds, ceil_log2(n) + n - 1) << n;
  }
}

TEST(MpiCollectiveSchedule, BinomialReduceAndItsNonCommutativeDetour) {
  const OpCase matrix = op_cases().back();
  for (int n : rank_counts)
    for (int root = 0; root < n; ++root)
      for (const OpCase* op : {&sum_int(), &matrix}) {
        const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int r) {
          Bytes result(r == root ? 3 * op->reduction.element_size : 0);
          reduce(call, op->data(r, 3), result, 3, op->reduction, root);
        });
        const bool detour = !op->reduction.commutative && root != 0;
        EXPECT_EQ(s.messages, sz(n - 1 + detour)) << n << " root " << root;
        EXPECT_EQ(s.rounds, ceil_log2(n) + detour) << n << " root " << root;
        EXPECT_EQ(s.reduction_bytes, sz(n - 1) * 3 * op->reduction.element_size);
      }
}

TEST(MpiCollectiveSchedule, RecursiveDoublingAllreduceIsNLog2NOnAPowerOfTwoPlusTheFold) {
  for (int n : rank_counts) {
    const int p = floor_pow2(n), rem = n - p, lg = ceil_log2(p);
    const ScheduleStats s = allreduce_stats(n, A::RecursiveDoubling, 8);
    EXPECT_EQ(s.messages, sz(p * lg + 2 * rem)) << n;
    EXPECT_EQ(s.rounds, lg + (rem > 0 ? 2 : 0)) << n;
    EXPECT_EQ(s.reduction_bytes, sz(p * lg + rem) * 8 * 4) << n;  // every exchange and fold combines 8 ints
  }
}

TEST(MpiCollectiveSchedule, RingAllreduceIsTwoNTimesNMinusOneMessagesInTwoNMinusTwoRounds) {
  for (int n : rank_counts) {
    const ScheduleStats s = allreduce_stats(n, A::Ring, sz(4 * n));
    EXPECT_EQ(s.messages, sz(2 * n * (n - 1))) << n;
    EXPECT_EQ(s.rounds, 2 * (n - 1)) << n;
    EXPECT_EQ(s.bytes, sz(2 * n * (n - 1)) * 4 * 4) << n;  // pieces of 4 ints
  }
}

// Rabenseifner on a power of two moves 2(n-1)/n of the vector per rank and reduces (n-1)/n of it.
TEST(MpiCollectiveSchedule, RabenseifnerAllreduceHalvesThenDoubles) {
  for (int n : rank_counts) {
    const int p = floor_pow2(n), rem = n - p, lg = ceil_log2(p);
    const std::size_t count = sz(8 * n), vector_bytes = count * 4;
    const ScheduleStats s = allreduce_stats(n, A::Rabenseifner, count);
    EXPECT_EQ(s.messages, sz(2 * p * lg + 2 * rem)) << n;
    EXPECT_EQ(s.rounds, 2 * lg + (rem > 0 ? 2 : 0)) << n;
    if (rem == 0) {
      EXPECT_EQ(s.bytes, sz(2 * (n - 1)) * vector_bytes) << n;
      EXPECT_EQ(s.reduction_bytes, sz(n - 1) * vector_bytes) << n;
    }
  }
}

TEST(MpiCollectiveSchedule, FallbacksRunTheNamedAlgorithmsSchedule) {
  const OpCase matrix = op_cases().back();
  for (int n : {3, 5, 8}) {
    const ScheduleStats ring = allreduce_stats(n, A::Ring, 16, matrix), rd = allreduce_stats(n, A::RecursiveDoubling, 16, matrix);
    EXPECT_EQ(ring.messages, rd.messages) << "ring with a non-commutative op runs recursive doubling";
    const ScheduleStats short_raben = allreduce_stats(n, A::Rabenseifner, 1), short_rd = allreduce_stats(n, A::RecursiveDoubling, 1);
    EXPECT_EQ(short_raben.messages, short_rd.messages) << "Rabenseifner with count < p runs recursive doubling";
  }
}

TEST(MpiCollectiveSchedule, GatherAndScatterTrees) {
  for (int n : rank_counts)
    for (A a : {A::Binomial, A::Linear}) {
      const ScheduleStats g = stats_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(r == 0 ? sz(n) * 4 : 0);
        gather(call, pattern(r, 4), result, 0, a);
      });
      const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(4);
        scatter(call, r == 0 ? pattern(0, sz(n) * 4) : Bytes{}, result, 0, a);
      });
      EXPECT_EQ(g.messages, sz(n - 1));
      EXPECT_EQ(s.messages, sz(n - 1));
      // Linear: the root takes (hands out) one block per step.
      EXPECT_EQ(g.rounds, a == A::Binomial ? ceil_log2(n) : n - 1) << n;
      EXPECT_EQ(s.rounds, a == A::Binomial ? ceil_log2(n) : n - 1) << n;
      if (a == A::Linear) {
        EXPECT_EQ(g.bytes, 4 * sz(n - 1));
      } else if ((n & (n - 1)) == 0) {
        EXPECT_EQ(g.bytes, 4 * sz(n / 2 * ceil_log2(n))) << n;
      }
    }
}

TEST(MpiCollectiveSchedule, AllgatherRingRecursiveDoublingAndBruck) {
  for (int n : rank_counts)
    for (A a : {A::Ring, A::RecursiveDoubling, A::Bruck}) {
      const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int) {
        Bytes result(sz(n) * 5);
        allgather(call, result, 5, a);
      });
      const bool logarithmic = a == A::Bruck || (a == A::RecursiveDoubling);  // RD on other n runs Bruck
      EXPECT_EQ(s.messages, logarithmic ? sz(n * ceil_log2(n)) : sz(n * (n - 1))) << algorithm_name(a) << " " << n;
      EXPECT_EQ(s.rounds, logarithmic ? ceil_log2(n) : n - 1) << algorithm_name(a) << " " << n;
      EXPECT_EQ(s.bytes, sz(n * (n - 1)) * 5) << algorithm_name(a) << " " << n;
    }
}

// Bruck alltoall: block at position i travels popcount(i) hops.
TEST(MpiCollectiveSchedule, AlltoallPairwiseLinearAndBruck) {
  for (int n : rank_counts)
    for (A a : {A::Pairwise, A::Linear, A::Bruck}) {
      const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(sz(n) * 3);
        alltoall(call, pattern(r, sz(n) * 3), result, 3, a);
      });
      std::size_t hops = 0;
      for (int i = 0; i < n; ++i) hops += sz(std::popcount(static_cast<unsigned>(i)));
      EXPECT_EQ(s.messages, a == A::Bruck ? sz(n * ceil_log2(n)) : sz(n * (n - 1))) << algorithm_name(a) << " " << n;
      EXPECT_EQ(s.rounds, a == A::Bruck ? ceil_log2(n) : n - 1) << algorithm_name(a) << " " << n;
      EXPECT_EQ(s.bytes, a == A::Bruck ? sz(n) * hops * 3 : sz(n * (n - 1)) * 3) << algorithm_name(a) << " " << n;
    }
}

TEST(MpiCollectiveSchedule, ReduceScatterPairwiseAndReduceThenScatter) {
  for (int n : rank_counts)
    for (A a : {A::Pairwise, A::ReduceThenScatter}) {
      const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(2 * 4);
        reduce_scatter_block(call, sum_int().data(r, sz(2 * n)), result, 2, sum_int().reduction, a);
      });
      EXPECT_EQ(s.messages, a == A::Pairwise ? sz(n * (n - 1)) : sz(2 * (n - 1))) << algorithm_name(a) << " " << n;
      EXPECT_EQ(s.rounds, a == A::Pairwise ? n - 1 : (n > 1 ? ceil_log2(n) + n - 1 : 0)) << algorithm_name(a) << " " << n;
    }
}

// On a power of two each rank hands on p/2 + p/4 + ... + 1 = p-1 blocks and reduces as many.
TEST(MpiCollectiveSchedule, RecursiveHalvingReduceScatterIsPLog2PMessagesPlusTheFold) {
  for (int n : rank_counts) {
    const int p = floor_pow2(n), rem = n - p, lg = ceil_log2(p);
    const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int r) {
      Bytes result(2 * 4);
      reduce_scatter_block(call, sum_int().data(r, sz(2 * n)), result, 2, sum_int().reduction, A::RecursiveHalving);
    });
    EXPECT_EQ(s.messages, sz(p * lg + 2 * rem)) << n;
    EXPECT_EQ(s.rounds, lg + (rem > 0 ? 2 : 0)) << n;
    if (rem == 0) {
      EXPECT_EQ(s.bytes, sz(n * (n - 1)) * 2 * 4) << n;
      EXPECT_EQ(s.reduction_bytes, sz(n * (n - 1)) * 2 * 4) << n;
    }
  }
}

TEST(MpiCollectiveSchedule, ScanAndExscanRecursiveDoublingAndChain) {
  for (int n : rank_counts)
    for (A a : {A::RecursiveDoubling, A::Linear})
      for (bool inclusive : {true, false}) {
        const ScheduleStats s = stats_of(n, [&](const CollectiveCall& call, int r) {
          Bytes result(4 * 4);
          if (inclusive) scan(call, sum_int().data(r, 4), result, 4, sum_int().reduction, a);
          else exscan(call, sum_int().data(r, 4), result, 4, sum_int().reduction, a);
        });
        std::size_t pairs = 0;  // ranks with a partner at distance 2^k inside the communicator
        for (int mask = 1; mask < n; mask *= 2)
          for (int r = 0; r < n; ++r) pairs += (r ^ mask) < n;
        EXPECT_EQ(s.messages, a == A::Linear ? sz(n - 1) : pairs) << algorithm_name(a) << " " << n;
        EXPECT_EQ(s.rounds, a == A::Linear ? n - 1 : ceil_log2(n)) << algorithm_name(a) << " " << n;
      }
}

}  // namespace
}  // namespace gcsim::mpi_layer::testing
