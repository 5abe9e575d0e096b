// A rank's computation: what gcsim_mpi_compute(_flops) annotates, and under --compute measured the
// host CPU time between its calls. Ranks switch only inside calls (all on one host thread), so the
// thread's CPU time from leaving the outermost call to entering the next is this rank's own; what
// gcsim does inside a call (matching, the network, other ranks) lies between entry and exit.
#include "apps/mpi/runtime/rank.hpp"

#include <algorithm>
#include <cmath>

namespace gcsim::mpi_layer {

void Rank::charge_compute(double node_seconds, const char* what) {
  const machine::SimTime d = machine::from_seconds(node_seconds);
  if (d <= 0) return;
  leave_cpu();
  mailbox_.occupy(d, what, false);
  install();
}

void Rank::compute(double seconds) {
  if (!(seconds >= 0)) fail(MPI_ERR_ARG, "negative compute time");
  if (computing.settings.mode == ComputeMode::none) return;
  charge_compute(seconds, "gcsim_mpi_compute");
}

void Rank::compute_flops(double flops) {
  if (!(flops >= 0)) fail(MPI_ERR_ARG, "negative flop count");
  if (computing.settings.mode == ComputeMode::none) return;
  if (!std::isfinite(computing.settings.seconds_per_flop)) {
    fail(MPI_ERR_OTHER, "gcsim_mpi_compute_flops: the machine file has no [ops] flop (cycles per flop)");
  }
  charge_compute(flops * computing.settings.seconds_per_flop, "gcsim_mpi_compute_flops");
}

// Under --compute none the host CPU time is never charged (sampled bodies neither), so the meter
// does not read the clock: CLOCK_THREAD_CPUTIME_ID is a system call, two per MPI call otherwise.
namespace {
bool reads_clock(const RankCompute& c) { return c.settings.mode != ComputeMode::none; }
}  // namespace

void Rank::start_computing() {
  computing.meter.depth = 0;
  if (reads_clock(computing)) computing.meter.left_at = thread_cpu_seconds();
}

void Rank::enter_call() {
  ComputeMeter& m = computing.meter;
  if (m.depth == 0 && reads_clock(computing)) {
    const double host = std::max(0.0, thread_cpu_seconds() - m.left_at);
    m.own += host;
    if (computing.settings.mode == ComputeMode::measured) {
      const double node = host * computing.host_ratio();
      if (computing.settings.totals) computing.settings.totals->measured_seconds += node;
      charge_compute(node, "measured_compute");
    }
  }
  ++m.depth;  // last: when the charge above unwinds (an abandoned run) no exit follows
}

void Rank::leave_call() {
  ComputeMeter& m = computing.meter;
  if (m.depth > 0 && --m.depth == 0 && reads_clock(computing)) m.left_at = thread_cpu_seconds();
}

}  // namespace gcsim::mpi_layer
