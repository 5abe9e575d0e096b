#pragma once
// The sites of the sampling macros GCSIM_SAMPLE_LOCAL / GCSIM_SAMPLE_GLOBAL (<gcsim/mpi_ext.h>):
// per site (file and line), how many bodies ran and their summed host CPU time, so later
// executions are skipped and charged the mean, as SMPI's SMPI_SAMPLE_LOCAL/GLOBAL do.
#include <map>
#include <string>

namespace gcsim::mpi_layer {

class Rank;

class SampleSites {
 public:
  struct Site {
    int samples = 0;          // bodies to run before skipping
    int finished = 0;         // bodies run to their end
    double host_seconds = 0;  // their summed host CPU time
    bool sampled() const { return finished >= samples; }
    double mean() const { return finished > 0 ? host_seconds / finished : 0.0; }
  };
  // The site of key, made with `samples` on first use; a later use with another count keeps the first.
  Site& site(const std::string& key, int samples) {
    auto [it, made] = sites_.try_emplace(key);
    if (made) it->second.samples = samples;
    return it->second;
  }

 private:
  std::map<std::string, Site> sites_;
};

// The macros' two calls: whether this execution's body runs (else it is charged the site's mean),
// and the end of a body that ran. Errors (samples < 1, an end without its start) are MPI errors.
bool begin_sample(Rank& rank, const char* file, int line, bool global, int samples);
void end_sample(Rank& rank, const char* file, int line, bool global);

}  // namespace gcsim::mpi_layer
