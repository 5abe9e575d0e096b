#pragma once
// What a rank's computation between MPI calls costs (gcsim mpirun --compute; apps/mpi/README.md
// "Computation"): nothing (none), only what the program annotates (annotated), or also the host
// CPU time the rank spent between leaving one call and entering the next, scaled by the host-to-node
// speed ratio (measured). All ranks run on one host thread but switch only inside calls, so the
// thread's CPU time between two calls is the running rank's own.
#include <optional>
#include <string>
#include <vector>

#include "apps/mpi/runtime/compute_samples.hpp"

namespace gcsim::mpi_layer {

class HostSpeed;

enum class ComputeMode { none, annotated, measured };
std::optional<ComputeMode> compute_mode_of(const std::string& name);
const char* compute_mode_name(ComputeMode mode);

// CLOCK_THREAD_CPUTIME_ID of the calling thread, in seconds.
double thread_cpu_seconds();

// What every rank's program charged, summed over the run (the run's JSON reports it).
struct ComputeTotals {
  double measured_seconds = 0;    // node seconds charged for measured host CPU time
  double sampled_seconds = 0;     // node seconds charged by sampled and skipped bodies
  long long bodies_run = 0;       // sampled bodies executed
  long long bodies_skipped = 0;   // bodies skipped and charged their site's mean
};

struct ComputeSettings {
  ComputeMode mode = ComputeMode::annotated;  // a Rank made outside mpirun stays deterministic
  double seconds_per_flop = 1.0 / 80e6;       // the node's: [ops] flop cycles / clock (mpirun sets it)
  HostSpeed* host_speed = nullptr;            // the run's host-to-node ratio; null: 1
  SampleSites* global_samples = nullptr;      // GCSIM_SAMPLE_GLOBAL's sites, one table per run
  ComputeTotals* totals = nullptr;            // the run's sums; null: not kept
};

// One rank's account of its own host CPU time. Calls nest (MPI_Finalize runs a barrier): only the
// outermost one's entry and exit are marks.
struct ComputeMeter {
  int depth = 0;
  double left_at = 0;   // thread CPU time when the last outermost call was left
  double own = 0;       // this rank's CPU seconds outside calls so far
};

// A body of a sampling macro that runs, from its start to GCSIM_SAMPLE's end call.
struct OpenSample {
  std::string key;
  SampleSites::Site* site = nullptr;
  double own_at_start = 0;
};

struct RankCompute {
  ComputeSettings settings;
  ComputeMeter meter;
  SampleSites local_samples;  // GCSIM_SAMPLE_LOCAL's sites, this rank's own
  std::vector<OpenSample> open;
  double host_ratio() const;  // host seconds -> node seconds (1 without a host speed)
};

}  // namespace gcsim::mpi_layer
