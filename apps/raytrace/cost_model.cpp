#include "apps/raytrace/cost_model.hpp"

namespace gcsim::raytrace {

machine::SimTime single_cpu_time(const TraceCounters& counters, const machine::MachineConfig& config) {
  machine::SimTime t = 0;
  for (const auto& [op, count] : counters.ops())
    if (count > 0) t += machine::op_time(config, op, count);
  return t;
}

}  // namespace gcsim::raytrace
