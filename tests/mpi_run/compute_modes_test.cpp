// What computation between MPI calls costs under each --compute mode, on ranks run in this process.
// Measured: a busy loop's charge grows with the loop (doubling it gives 1.6x to 2.4x: host CPU time
// of a dependent chain is close to linear in its length, and the median of five pairs rides out
// interruptions) and with the host speed (ratio 3 against 1 gives 2.4x to 3.6x). Annotated flops are
// charged exactly flops x [ops] flop cycles / clock, whatever the host speed. The sampling macros
// run the first k bodies and charge every later execution the mean of those, so n executions
// charge n x mean (to the picosecond of each charge's rounding).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "apps/mpi/include/gcsim/mpi_ext.h"
#include "apps/mpi/include/mpi.h"
#include "apps/mpi/runtime/host_speed.hpp"
#include "apps/mpi/runtime/rank.hpp"
#include "machine/machine_config.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::mpi_layer {
namespace {

using machine::SimTime;
SimTime picoseconds(double seconds) { return std::llround(seconds * 1e12); }

// A dependent multiply-add chain: no vectorizing, time linear in n.
double busy(long n) {
  double x = 1.0;
  for (long i = 0; i < n; ++i) x = x * 1.0000001 + 1e-9;
  return x;
}
volatile double sink = 0;

parix::SimulationOptions machine_of(int nodes) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::default_machine_config(), nodes);
  return o;
}

// Runs body(rank) on every rank with the given settings between MPI_Init and the end.
template <class Body>
void run_ranks(int nodes, const ComputeSettings& settings, Body body) {
  const parix::SimulationOptions o = machine_of(nodes);
  parix::run_simulated(o, [&](parix::Processor& p) {
    Rank rank(p, o.config.mpi);
    rank.computing.settings = settings;
    rank.install();
    rank.start_computing();
    MPI_Init(nullptr, nullptr);
    body(rank);
    install_registry(nullptr);
  });
}

// Simulated seconds charged for busy(n) between two MPI_Wtime calls under --compute measured.
double measured_charge(long n, HostSpeed& speed) {
  ComputeSettings s;
  s.mode = ComputeMode::measured;
  s.host_speed = &speed;
  double charged = 0;
  run_ranks(1, s, [&](Rank&) {
    const double t0 = MPI_Wtime();
    sink = busy(n);
    charged = MPI_Wtime() - t0;
  });
  return charged;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

HostSpeed ratio_speed(const std::string& ratio) { return HostSpeed(parse_host_speed(ratio), "daxpy", 80e6); }

TEST(MpiComputeMeasured, DoublingABusyLoopRoughlyDoublesItsCharge) {
  HostSpeed speed = ratio_speed("1");
  std::vector<double> ratios;
  for (int pair = 0; pair < 5; ++pair) {
    const double once = measured_charge(10'000'000, speed);
    const double twice = measured_charge(20'000'000, speed);
    ASSERT_GT(once, 0);
    ratios.push_back(twice / once);
  }
  const double r = median(ratios);
  EXPECT_GE(r, 1.6);
  EXPECT_LE(r, 2.4);
}

TEST(MpiComputeMeasured, TheChargeScalesWithTheHostSpeedRatio) {
  HostSpeed one = ratio_speed("1"), three = ratio_speed("3");
  std::vector<double> ratios;
  for (int pair = 0; pair < 5; ++pair) {
    const double slow = measured_charge(10'000'000, one);
    ratios.push_back(measured_charge(10'000'000, three) / slow);
  }
  const double r = median(ratios);
  EXPECT_GE(r, 3 * 0.8);
  EXPECT_LE(r, 3 * 1.2);
}

TEST(MpiComputeMeasured, AnnotatedModeChargesNothingForTheSameLoop) {
  ComputeSettings s;  // annotated: the default of a Rank made outside mpirun
  double charged = -1;
  run_ranks(1, s, [&](Rank&) {
    const double t0 = MPI_Wtime();
    sink = busy(10'000'000);
    charged = MPI_Wtime() - t0;
  });
  EXPECT_EQ(charged, 0.0);
}

// Simulated picoseconds of gcsim_mpi_compute_flops(flops) in mode under the given host speed.
SimTime flops_charge(double flops, ComputeMode mode, HostSpeed& speed) {
  ComputeSettings s;
  s.mode = mode;
  s.host_speed = &speed;
  const machine::MachineConfig c = machine::default_machine_config();
  s.seconds_per_flop = c.cycles_per_op.at("flop") / c.clock_hz;
  SimTime charged = 0;
  run_ranks(1, s, [&](Rank&) {
    const double t0 = MPI_Wtime();
    EXPECT_EQ(gcsim_mpi_compute_flops(flops), MPI_SUCCESS);
    charged = picoseconds(MPI_Wtime()) - picoseconds(t0);
  });
  return charged;
}

TEST(MpiComputeAnnotated, FlopsAreChargedAtTheNodesRateWhateverTheHostSpeed) {
  const machine::MachineConfig c = machine::default_machine_config();
  const double flops = 12'345'678;
  const SimTime expected = machine::from_seconds(flops * c.cycles_per_op.at("flop") / c.clock_hz);
  for (const char* ratio : {"1", "3.7", "250"}) {
    HostSpeed speed = ratio_speed(ratio);
    EXPECT_EQ(flops_charge(flops, ComputeMode::annotated, speed), expected) << "host speed " << ratio;
  }
  HostSpeed speed = ratio_speed("2");
  EXPECT_EQ(flops_charge(flops, ComputeMode::none, speed), 0);
}

TEST(MpiHostSpeed, RatiosRatesAndAutoAreReadAndBadOnesRefused) {
  HostSpeed rate(parse_host_speed("160Mf"), "daxpy", 80e6);
  EXPECT_EQ(rate.ratio(), 2.0);
  HostSpeed giga(parse_host_speed("2Gflops"), "daxpy", 80e6);
  EXPECT_EQ(giga.ratio(), 25.0);
  HostSpeed given = ratio_speed("0.5");
  EXPECT_EQ(given.ratio(), 0.5);
  HostSpeed automatic(parse_host_speed("auto"), "daxpy", 80e6);
  EXPECT_FALSE(automatic.known());
  const double measured = automatic.ratio();  // timed once, then kept
  EXPECT_GT(measured, 0);
  EXPECT_EQ(automatic.ratio(), measured);
  for (const char* bad : {"fast", "-1", "0", "3Xf", "", "2Gf3", "nan"}) {
    EXPECT_THROW(parse_host_speed(bad), std::invalid_argument) << bad;
  }
  EXPECT_THROW(measure_host_flops("linpack"), std::invalid_argument);
}

// Per rank: each execution's charged picoseconds and how many bodies ran.
struct Sampled {
  std::vector<SimTime> charged;
  int ran = 0;
};

Sampled sample_loop(int executions, bool global, int samples) {
  Sampled s;
  double t = MPI_Wtime();
  for (int i = 0; i < executions; ++i) {
    if (global) {
      GCSIM_SAMPLE_GLOBAL(samples) {
        sink = busy(200'000 * (1 + i % 2));  // bodies that differ: the mean is not any one of them
        ++s.ran;
      }
    } else {
      GCSIM_SAMPLE_LOCAL(samples) {
        sink = busy(200'000 * (1 + i % 2));
        ++s.ran;
      }
    }
    const double now = MPI_Wtime();
    s.charged.push_back(picoseconds(now) - picoseconds(t));
    t = now;
  }
  return s;
}

TEST(MpiComputeSampling, LocalSitesChargeNTimesTheMeanOfTheirSampledBodies) {
  HostSpeed speed = ratio_speed("2");
  ComputeSettings s;
  s.host_speed = &speed;
  ComputeTotals totals;
  s.totals = &totals;
  std::vector<Sampled> by_rank(2);
  run_ranks(2, s, [&](Rank& r) { by_rank[static_cast<std::size_t>(r.world_rank())] = sample_loop(10, false, 3); });
  for (const Sampled& one : by_rank) {
    EXPECT_EQ(one.ran, 3);
    SimTime sampled = 0;
    for (int i = 0; i < 3; ++i) sampled += one.charged[static_cast<std::size_t>(i)];
    ASSERT_GT(sampled, 0);
    SimTime total = 0;
    for (SimTime c : one.charged) total += c;
    for (std::size_t i = 3; i < one.charged.size(); ++i) EXPECT_NEAR(one.charged[i], sampled / 3.0, 2) << i;
    EXPECT_NEAR(static_cast<double>(total), 10 * (sampled / 3.0), 20);
  }
  EXPECT_EQ(totals.bodies_run, 6);
  EXPECT_EQ(totals.bodies_skipped, 14);
}

TEST(MpiComputeSampling, GlobalSitesShareTheirSamplesAmongRanks) {
  HostSpeed speed = ratio_speed("1");
  SampleSites shared;
  ComputeSettings s;
  s.host_speed = &speed;
  s.global_samples = &shared;
  std::vector<Sampled> by_rank(4);
  run_ranks(4, s, [&](Rank& r) { by_rank[static_cast<std::size_t>(r.world_rank())] = sample_loop(5, true, 3); });
  int ran = 0;
  SimTime sampled = 0;
  std::vector<SimTime> skipped;
  for (const Sampled& one : by_rank) {
    ran += one.ran;
    for (int i = 0; i < 5; ++i) {
      (i < one.ran ? sampled : skipped.emplace_back()) += one.charged[static_cast<std::size_t>(i)];
    }
  }
  EXPECT_EQ(ran, 3);  // no body calls MPI, so no rank starts one while another's is unfinished
  ASSERT_EQ(skipped.size(), 17u);
  for (SimTime c : skipped) EXPECT_NEAR(c, sampled / 3.0, 2);
}

TEST(MpiComputeSampling, NoneRunsTheSameBodiesAndChargesNothing) {
  ComputeSettings s;
  s.mode = ComputeMode::none;
  Sampled one;
  run_ranks(1, s, [&](Rank&) { one = sample_loop(6, false, 2); });
  EXPECT_EQ(one.ran, 2);
  for (SimTime c : one.charged) EXPECT_EQ(c, 0);
}

}  // namespace
}  // namespace gcsim::mpi_layer
