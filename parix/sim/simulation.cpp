// A simulated run from start to result: the processors' processes made and run (ProcessLifetime),
// then the run's figures.
#include "parix/sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "parix/host/interruption.hpp"

namespace gcsim::parix {
namespace detail {

std::deque<machine::Node> Simulation::make_nodes(machine::Kernel& kernel, const machine::MachineConfig& config,
                                                 machine::MemoryLimit limit) {
  std::deque<machine::Node> nodes;
  for (int n = 0; n < config.nodes; ++n) nodes.emplace_back(kernel, config.cpus_per_node, config.memory_bytes, limit);
  return nodes;
}

RunResult Simulation::run(const std::function<void(Processor&)>& program) {
  const auto wall_start = std::chrono::steady_clock::now();
  for (int i = 0; i < processors; ++i) processes.add(std::make_unique<SimProcess>(*this, i, 0));
  const ProcessLifetime::End end = processes.run(program);
  trace.close();
  if (processes.failure()) std::rethrow_exception(processes.failure());
  if (end == ProcessLifetime::End::deadlock) throw DeadlockError(processes.deadlock_report());
  if (end == ProcessLifetime::End::interrupted) throw host::Interrupted(result(wall_start, true));
  return result(wall_start, false);
}

RunResult Simulation::result(std::chrono::steady_clock::time_point wall_start, bool interrupted) const {
  RunResult r;
  r.model = std::string(network->name());
  r.config_name = config.name;
  r.nodes = config.nodes;
  r.events = kernel.events_processed();
  r.link_end_slots = static_cast<std::int64_t>(links.slots());
  r.processors = stats;
  if (interrupted) r.makespan = kernel.now();  // the simulated time reached
  for (int i = 0; i < processors; ++i) {
    const machine::NodeMemory& m = memory.of(i);
    if (m.peak() > r.memory_peak) r.memory_peak = m.peak(), r.memory_peak_processor = i;
  }
  r.memory_capacity = config.memory_bytes;
  r.memory_warning = memory.warning();
  for (const auto& s : stats) r.makespan = std::max(r.makespan, s.finish);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return r;
}

}  // namespace detail

RunResult run_simulated(const SimulationOptions& options, const std::function<void(Processor&)>& program) {
  detail::Simulation sim(options);
  return sim.run(program);
}

}  // namespace gcsim::parix
