#include "apps/mpi/app/run_computing.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "apps/pipeline/command_groups.hpp"

namespace gcsim::mpi_layer::app {
namespace {

// Cycles of the first of ops the machine file's [ops] gives; NaN when it gives none (then the
// calls that need it fail, naming it).
double cycles_of(const machine::MachineConfig& config, std::initializer_list<const char*> ops) {
  for (const char* op : ops) {
    if (const auto it = config.cycles_per_op.find(op); it != config.cycles_per_op.end()) return it->second;
  }
  return NAN;
}

}  // namespace

RunComputing::RunComputing(const MpirunOptions& o, const machine::MachineConfig& config)
    : host_speed(o.host_speed, "daxpy", config.clock_hz / cycles_of(config, {"daxpy_flop", "flop"})) {
  settings.mode = *compute_mode_of(o.compute);
  settings.seconds_per_flop = cycles_of(config, {"flop"}) / config.clock_hz;
  settings.host_speed = &host_speed;
  settings.global_samples = &global_samples;
  settings.totals = &totals;
  if (o.host_speed.kind != HostSpeedChoice::Kind::ratio && !std::isfinite(host_speed.node_flops())) {
    std::fprintf(stderr, "gcsim mpirun: --host-speed %s needs the node's rate: %s's [ops] gives neither daxpy_flop nor flop\n",
                 o.host_speed.text.c_str(), config.source.c_str());
    throw pipeline::ExitStatus{2};
  }
  if (settings.mode == ComputeMode::measured) host_speed.ratio();
}

void RunComputing::print() const {
  std::printf("compute   %s: %.6f s measured, %.6f s sampled (%lld bodies run, %lld skipped); %s\n",
              compute_mode_name(settings.mode), totals.measured_seconds, totals.sampled_seconds, totals.bodies_run,
              totals.bodies_skipped, host_speed.summary().c_str());
}

nlohmann::json RunComputing::to_json() const {
  return {{"mode", compute_mode_name(settings.mode)},
          {"host_speed", host_speed.to_json()},
          {"measured_seconds", totals.measured_seconds},
          {"sampled_seconds", totals.sampled_seconds},
          {"sampled_bodies_run", totals.bodies_run},
          {"sampled_bodies_skipped", totals.bodies_skipped}};
}

}  // namespace gcsim::mpi_layer::app
