// A non-blocking allreduce overlaps the rank's computation and its waits on other requests: the
// simulated times equal the schedule computed by hand from the analytic model's T(h, n) and the
// [mpi] overheads c = o + G n and R = reduce cost per byte x n, to the picosecond. On two ranks
// the recursive-doubling allreduce is one exchange: each rank posts its receive, sends (c, then
// the message leaves and arrives T later), and once the partner's message is in pays c for it and
// R to combine. Started, then C seconds of annotated computation, then the wait, rank r leaves at
//   max(e_r + c + C, e_p + c + T) + c + R      (overlap: max(C, T) and the overheads)
// where the blocking allreduce followed by the same computation leaves at
//   max(e_r + c, e_p + c + T) + c + R + C.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "apps/mpi/include/gcsim/mpi_ext.h"
#include "apps/mpi/include/mpi.h"
#include "apps/mpi/runtime/rank.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/mpi_run/analytic_row.hpp"

namespace gcsim::mpi_layer::nonblocking_overlap {  // its own: the unity build puts the timing tests in one file
namespace {

constexpr int kRanks = 2;
constexpr int kDoubles = 125;
constexpr int kBytes = kDoubles * 8;

using machine::SimTime;

std::unique_ptr<AnalyticRow> pair_of_nodes() { return analytic_row(kRanks, kBytes, 5e-9); }

struct Times {
  std::vector<SimTime> entered = std::vector<SimTime>(kRanks), left = std::vector<SimTime>(kRanks);
  std::vector<double> sums = std::vector<double>(kRanks);
};

// Each rank: a warm-up allreduce (every connection set up), a barrier, then `step` timed.
template <class Step>
Times measure(const parix::SimulationOptions& o, Step step) {
  Times t;
  parix::run_simulated(o, [&](parix::Processor& p) {
    Rank rank(p, o.config.mpi);
    rank.collective_algorithms.set(Collective::Allreduce, Algorithm::RecursiveDoubling);
    rank.install();
    MPI_Init(nullptr, nullptr);
    std::vector<double> mine(kDoubles, p.id() + 1.0), sum(kDoubles);
    MPI_Allreduce(mine.data(), sum.data(), kDoubles, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    MPI_Barrier(MPI_COMM_WORLD);
    const auto me = static_cast<std::size_t>(p.id());
    t.entered[me] = picoseconds(MPI_Wtime());
    step(p.id(), mine, sum);
    t.left[me] = picoseconds(MPI_Wtime());
    t.sums[me] = sum[kDoubles - 1];
    install_registry(nullptr);  // no MPI_Finalize: its barrier is not part of the schedule
  });
  return t;
}

void overlapped(double compute_seconds, int, std::vector<double>& mine, std::vector<double>& sum) {
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Iallreduce(mine.data(), sum.data(), kDoubles, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD, &request);
  gcsim_mpi_compute(compute_seconds);
  MPI_Wait(&request, MPI_STATUS_IGNORE);
}

void blocking(double compute_seconds, int, std::vector<double>& mine, std::vector<double>& sum) {
  MPI_Allreduce(mine.data(), sum.data(), kDoubles, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  gcsim_mpi_compute(compute_seconds);
}

class NonblockingOverlap : public ::testing::TestWithParam<double> {};

TEST_P(NonblockingOverlap, IallreduceTakesTheMaximumOfComputeAndTransfer) {
  const auto m = pair_of_nodes();
  const double compute = GetParam();
  const SimTime c = m->cpu, C = machine::from_seconds(compute), T = m->transit(0, 1);
  const Times t = measure(m->options, [&](int me, auto& mine, auto& sum) { overlapped(compute, me, mine, sum); });
  const Times b = measure(m->options, [&](int me, auto& mine, auto& sum) { blocking(compute, me, mine, sum); });
  for (int r = 0; r < kRanks; ++r) {
    const auto i = static_cast<std::size_t>(r), p = static_cast<std::size_t>(1 - r);
    EXPECT_EQ(t.sums[i], 3.0);
    EXPECT_EQ(t.left[i], std::max(t.entered[i] + c + C, t.entered[p] + c + T) + c + m->reduce) << "rank " << r;
    EXPECT_EQ(b.left[i], std::max(b.entered[i] + c, b.entered[p] + c + T) + c + m->reduce + C) << "rank " << r;
    EXPECT_LT(t.left[i] - t.entered[i], b.left[i] - b.entered[i]) << "rank " << r;  // the overlap saves time
  }
}

// Computation longer than the transfer (the transfer hidden), and shorter (the computation hidden).
INSTANTIATE_TEST_SUITE_P(ComputeAgainstTransfer, NonblockingOverlap, ::testing::Values(1e-3, 2e-6));

// Rank 0 starts the allreduce and then blocks in a receive that rank 1 sends only after computing
// C: the partner's allreduce message wakes rank 0 inside that receive, and the schedule finishes
// there, so the wait after the receive costs nothing. Rank 0's allreduce ends at
//   A = max(e_0 + c, e_1 + c + T) + c + R,
// the receive at max(A, e_1 + c + C + c + T) + c; without progress inside the receive, the
// allreduce's c + R would come after it.
TEST(NonblockingProgress, AScheduleAdvancesWhileTheRankWaitsForAnotherRequest) {
  const auto m = pair_of_nodes();
  const double compute = 1e-3;
  const SimTime c = m->cpu, C = machine::from_seconds(compute);
  const SimTime message = m->network->uncontended_time(m->interconnect->hops(1, 0), sizeof(int));
  const Times t = measure(m->options, [&](int me, std::vector<double>& mine, std::vector<double>& sum) {
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Iallreduce(mine.data(), sum.data(), kDoubles, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD, &request);
    int token = 7;
    if (me == 1) {
      gcsim_mpi_compute(compute);
      MPI_Send(&token, 1, MPI_INT, 0, 0, MPI_COMM_WORLD);
    } else {
      MPI_Recv(&token, 1, MPI_INT, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    MPI_Wait(&request, MPI_STATUS_IGNORE);
  });
  const SimTime token_cpu = m->options.config.mpi.call_overhead + machine::from_seconds(m->options.config.mpi.seconds_per_byte * 4);
  const SimTime allreduce_done = std::max(t.entered[0] + c, t.entered[1] + c + m->transit(0, 1)) + c + m->reduce;
  const SimTime token_arrives = t.entered[1] + c + C + token_cpu + message;
  EXPECT_EQ(t.left[0], std::max(allreduce_done, token_arrives) + token_cpu);
  EXPECT_EQ(t.sums[0], 3.0);
}

}  // namespace
}  // namespace gcsim::mpi_layer::nonblocking_overlap
