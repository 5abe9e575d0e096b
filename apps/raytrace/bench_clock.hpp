#pragma once
// The clock of `gcsim bench raytrace`, for our frames and Embree's alike: the calling thread's CPU
// time. Every timed frame runs on that one thread, and on a host shared with other work its CPU
// time leaves out the time slices other processes got, which wall time counts at random.
#include <ctime>

namespace gcsim::raytrace {

inline double bench_thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace gcsim::raytrace
