// A binomial broadcast's and a ring allgather's simulated times equal their schedules computed by
// hand from the analytic model's own per-message time T(h, n) and the [mpi] overheads
// c = o + G n, as pingpong_timing_test.cpp does for a ping-pong. Collective messages are eager: a
// send holds the CPU for c and then leaves, arriving T(h, n) later; a receive completes at
// max(posted, arrived) and then holds the CPU for c. Each rank's entry time is measured (after a
// warm-up call that pays every pair's connection set-up), so the schedule starts from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "apps/mpi/include/mpi.h"
#include "apps/mpi/runtime/rank.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/mpi_run/analytic_row.hpp"

namespace gcsim::mpi_layer {
namespace {

constexpr int kRanks = 8;
constexpr int kBytes = 1000;

using machine::SimTime;

struct Times {
  std::vector<SimTime> entered = std::vector<SimTime>(kRanks), left = std::vector<SimTime>(kRanks);
};

// Every rank runs `collective` twice (a warm-up, then the measured call) on the row of 8 nodes.
template <class Collective>
Times measure(const parix::SimulationOptions& o, Algorithm algorithm, mpi_layer::Collective which, Collective collective) {
  Times t;
  parix::run_simulated(o, [&](parix::Processor& p) {
    Rank rank(p, o.config.mpi);
    rank.collective_algorithms.set(which, algorithm);
    rank.install();
    MPI_Init(nullptr, nullptr);
    collective();
    MPI_Barrier(MPI_COMM_WORLD);
    const auto me = static_cast<std::size_t>(p.id());
    t.entered[me] = picoseconds(MPI_Wtime());
    collective();
    t.left[me] = picoseconds(MPI_Wtime());
    install_registry(nullptr);
  });
  return t;
}

std::unique_ptr<AnalyticRow> row_of_eight() { return analytic_row(kRanks, kBytes); }

TEST(MpiCollectiveTiming, BinomialBroadcastFollowsItsTreeSchedule) {
  const auto m = row_of_eight();
  std::vector<char> buffer(kBytes);
  const Times t = measure(m->options, Algorithm::Binomial, Collective::Bcast,
                          [&] { MPI_Bcast(buffer.data(), kBytes, MPI_CHAR, 0, MPI_COMM_WORLD); });
  // Rank r (root 0) receives from r minus its lowest set bit, then sends to r + 2^k for the 2^k
  // below that bit, largest first; each send leaves after its c.
  std::vector<SimTime> ready(kRanks);
  ready[0] = t.entered[0];
  for (int r = 1; r < kRanks; ++r) {
    const int low = r & -r, parent = r - low;
    int order = 0;  // which of the parent's sends reaches r: the parent's masks above low come first
    for (int child = (parent == 0 ? kRanks : (parent & -parent)) / 2; child >= low; child /= 2) ++order;
    const SimTime arrived = ready[parent] + order * m->cpu + m->transit(parent, r);
    ready[r] = std::max(arrived, t.entered[r]) + m->cpu;
  }
  for (int r = 0; r < kRanks; ++r) {
    int children = 0;
    for (int child = (r == 0 ? kRanks : (r & -r)) / 2; child > 0; child /= 2) children += r + child < kRanks;
    EXPECT_EQ(t.left[r], ready[r] + children * m->cpu) << "rank " << r;
  }
  EXPECT_GT(t.left[kRanks - 1], t.entered[0] + 3 * m->cpu);  // three rounds at least
}

TEST(MpiCollectiveTiming, RingAllgatherFollowsItsRoundSchedule) {
  const auto m = row_of_eight();
  std::vector<char> mine(kBytes), all(static_cast<std::size_t>(kBytes) * kRanks);
  const Times t = measure(m->options, Algorithm::Ring, Collective::Allgather, [&] {
    MPI_Allgather(mine.data(), kBytes, MPI_CHAR, all.data(), kBytes, MPI_CHAR, MPI_COMM_WORLD);
  });
  // Each round a rank posts its receive, sends (c, then the message leaves), and once the left
  // neighbour's message is in, pays c for it: start' = max(start + c, arrival) + c.
  std::vector<SimTime> start = t.entered;
  for (int round = 0; round < kRanks - 1; ++round) {
    std::vector<SimTime> next(kRanks);
    for (int r = 0; r < kRanks; ++r) {
      const int left = (r + kRanks - 1) % kRanks;
      const SimTime arrived = start[static_cast<std::size_t>(left)] + m->cpu + m->transit(left, r);
      next[static_cast<std::size_t>(r)] = std::max(start[static_cast<std::size_t>(r)] + m->cpu, arrived) + m->cpu;
    }
    start = next;
  }
  for (int r = 0; r < kRanks; ++r) EXPECT_EQ(t.left[static_cast<std::size_t>(r)], start[static_cast<std::size_t>(r)]) << "rank " << r;
}

}  // namespace
}  // namespace gcsim::mpi_layer
