#include "apps/mpi/runtime/compute_meter.hpp"

#include <ctime>

#include "apps/mpi/runtime/host_speed.hpp"

namespace gcsim::mpi_layer {

std::optional<ComputeMode> compute_mode_of(const std::string& name) {
  if (name == "none") return ComputeMode::none;
  if (name == "annotated") return ComputeMode::annotated;
  if (name == "measured") return ComputeMode::measured;
  return std::nullopt;
}

const char* compute_mode_name(ComputeMode mode) {
  switch (mode) {
    case ComputeMode::none: return "none";
    case ComputeMode::annotated: return "annotated";
    case ComputeMode::measured: return "measured";
  }
  return "?";
}

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double RankCompute::host_ratio() const { return settings.host_speed ? settings.host_speed->ratio() : 1.0; }

}  // namespace gcsim::mpi_layer
