// The sampling macros' calls. A body that runs is timed as the rank's own CPU time between the
// begin call and the end call (ComputeMeter::own: CPU time spent inside calls in between, e.g. an
// MPI call in the body, is gcsim's or other ranks' and left out). Charged, scaled by the host
// speed: under annotated by end_sample; under measured by the meter already (it is time between
// calls); under none never. A skipped body is charged the site's mean under annotated and measured.
#include <string>

#include "apps/mpi/runtime/compute_meter.hpp"
#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {
namespace {

std::string site_key(const char* file, int line) { return std::string(file ? file : "?") + ":" + std::to_string(line); }

SampleSites& sites_of(Rank& rank, bool global) {
  SampleSites* shared = rank.computing.settings.global_samples;
  return global && shared ? *shared : rank.computing.local_samples;
}

}  // namespace

bool begin_sample(Rank& rank, const char* file, int line, bool global, int samples) {
  const std::string key = site_key(file, line);
  if (samples < 1) fail(MPI_ERR_ARG, ("GCSIM_SAMPLE at " + key + ": samples must be 1 or more, got " + std::to_string(samples)).c_str());
  RankCompute& c = rank.computing;
  for (const OpenSample& open : c.open) {  // a site cannot contain itself: its last body never ended
    if (open.key == key) fail(MPI_ERR_OTHER, ("GCSIM_SAMPLE at " + key + ": a body left by break, goto or return").c_str());
  }
  SampleSites::Site& site = sites_of(rank, global).site(key, samples);
  ComputeTotals* totals = c.settings.totals;
  if (site.sampled()) {
    if (totals) ++totals->bodies_skipped;
    if (c.settings.mode == ComputeMode::none) return false;
    const double node = site.mean() * c.host_ratio();
    if (totals) totals->sampled_seconds += node;
    rank.charge_compute(node, "sampled_compute");
    return false;
  }
  if (totals) ++totals->bodies_run;
  c.open.push_back({key, &site, c.meter.own});
  return true;
}

void end_sample(Rank& rank, const char* file, int line, bool global) {
  (void)global;
  const std::string key = site_key(file, line);
  RankCompute& c = rank.computing;
  if (c.open.empty() || c.open.back().key != key) {
    fail(MPI_ERR_OTHER, ("GCSIM_SAMPLE at " + key + ": an end without its start (a body left by break, goto or return?)").c_str());
  }
  const OpenSample s = c.open.back();
  c.open.pop_back();
  const double host = c.meter.own - s.own_at_start;
  s.site->host_seconds += host;
  ++s.site->finished;
  if (c.settings.mode != ComputeMode::annotated) return;  // measured: the meter charged it; none: nothing
  const double node = host * c.host_ratio();
  if (c.settings.totals) c.settings.totals->sampled_seconds += node;
  rank.charge_compute(node, "sampled_compute");
}

}  // namespace gcsim::mpi_layer
