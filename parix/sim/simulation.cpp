// The simulation loop: fibers run until all block, then the kernel advances to the next event;
// a run in which every processor is blocked and no event is pending is a deadlock.
#include <algorithm>
#include <chrono>
#include <vector>

#include <fmt/format.h>

#include "parix/sim/deadlock_report.hpp"
#include "parix/interruption.hpp"
#include "parix/sim/simulation.hpp"

namespace gcsim::parix {
namespace detail {

std::vector<int> checked_placement(const std::vector<int>& placement, int nodes) {
  std::vector<int> node_of(nodes);
  if (placement.empty()) {
    for (int i = 0; i < nodes; ++i) node_of[i] = i;
    return node_of;
  }
  if (static_cast<int>(placement.size()) != nodes) {
    throw ParixError(fmt::format("placement names {} nodes for {} processors (expected one node per processor)",
                                 placement.size(), nodes));
  }
  std::vector<bool> used(nodes, false);
  for (int i = 0; i < nodes; ++i) {
    const int n = placement[i];
    if (n < 0 || n >= nodes || used[n]) {
      throw ParixError(fmt::format("placement puts processor {} on node {} (expected each node 0..{} once)", i, n, nodes - 1));
    }
    used[n] = true;
    node_of[i] = n;
  }
  return node_of;
}

// ---- Simulation ------------------------------------------------------------------------------

std::string Simulation::deadlock_report() const {
  std::vector<BlockedProcess> blocked;
  for (const auto& p : processes) {
    if (!p->finished) blocked.push_back({p->id(), p->thread(), p->blocked_call, p->blocked_peer, p->blocked_since});
  }
  return parix::deadlock_report(kernel.now(), blocked);
}

RunResult Simulation::run(const std::function<void(Processor&)>& program) {
  const auto wall_start = std::chrono::steady_clock::now();
  for (int i = 0; i < config.nodes; ++i) processes.push_back(std::make_unique<SimProcess>(*this, i, 0));
  try {
    for (int i = 0; i < config.nodes; ++i) launch(processes[i].get(), program);
  } catch (...) {
    failure = std::current_exception();  // out of host memory: unwind what was launched
    cancelling = true;
  }

  bool deadlock = false;
  bool interrupted = false;
  for (;;) {
    fibers.run_ready();  // every woken fiber runs until it blocks or returns
    if (failure || live == 0) break;
    if (interruption_requested()) {  // SIGINT/SIGTERM (parix/interruption.hpp): one relaxed load per event
      interrupted = true;
      break;
    }
    if (!kernel.step()) {
      deadlock = true;
      break;
    }
  }
  std::string report;
  if (deadlock) report = deadlock_report();
  if (deadlock || failure || interrupted) {
    // Unwind every blocked fiber so that their stacks are released cleanly.
    cancelling = true;
    for (auto& p : processes) p->wake();
    fibers.run_ready();
  } else {
    kernel.run();  // messages still in flight after the last processor returned
  }
  fibers.join_all();
  trace.close();
  if (failure) std::rethrow_exception(failure);
  if (deadlock) throw DeadlockError(report);
  if (interrupted) throw Interrupted(result(wall_start, true));
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
  for (int i = 0; i < config.nodes; ++i) {
    const machine::NodeMemory& m = nodes[node_of[i]].memory();
    if (m.peak() > r.memory_peak) r.memory_peak = m.peak(), r.memory_peak_processor = i;
  }
  r.memory_capacity = config.memory_bytes;
  r.memory_warning = memory_warning;
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
