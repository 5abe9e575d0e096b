// gcsim's computation calls of <gcsim/mpi_ext.h>: annotated seconds and flops, and the two calls
// the sampling macros make. A sampling error ends the run with a message naming the site: the
// macros cannot return an error code to the program.
#include <cstdio>

#include "apps/mpi/include/gcsim/mpi_ext.h"
#include "apps/mpi/runtime/compute_samples.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

namespace {

template <class F>
int sampling_call(F&& body) {
  int result = 0;
  runtime_call([&](Rank& rank) {
    try {
      result = body(rank);
    } catch (const Error& e) {
      std::fprintf(stderr, "gcsim: rank %d: %s\n", rank.world_rank(), e.what());
      throw AbortRequested{rank.world_rank(), 2};
    }
  });
  return result;
}

}  // namespace

extern "C" {

int gcsim_mpi_compute(double seconds) {
  return runtime_call([&](Rank& rank) { rank.compute(seconds); });
}

int gcsim_mpi_compute_flops(double flops) {
  return runtime_call([&](Rank& rank) { rank.compute_flops(flops); });
}

int gcsim_mpi_sample_begin(const char* file, int line, int global, int samples) {
  return sampling_call([&](Rank& rank) { return begin_sample(rank, file, line, global != 0, samples) ? 1 : 0; });
}

int gcsim_mpi_sample_end(const char* file, int line, int global) {
  return sampling_call([&](Rank& rank) {
    end_sample(rank, file, line, global != 0);
    return 0;
  });
}

}  // extern "C"
