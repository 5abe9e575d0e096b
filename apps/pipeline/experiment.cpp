#include "apps/pipeline/experiment.hpp"

#include <fmt/format.h>

#include "parix/host/interruption.hpp"

namespace gcsim::pipeline {

std::unique_ptr<Outcome> run_experiment(const Experiment& e, const parix::RunOptions& options, nlohmann::json* reached) {
  const int nodes = options.simulation.config.nodes;
  int fullest = 0;
  const std::vector<MemoryNeed> needs = e.node_memory(nodes, &fullest);
  check_node_memory(needs, fullest, options.simulation.config.memory_bytes, options.simulation.memory_limit);
  check_host_memory(e.host_memory(nodes), fmt::format("a run on {} nodes", nodes));
  std::unique_ptr<Outcome> out = e.new_outcome(nodes);
  out->options = options;
  try {
    out->run = parix::run(options, e.program(*out));
  } catch (const parix::host::Interrupted&) {
    if (reached) e.report_interrupted(*out, *reached);
    throw;
  }
  e.after_run(*out);
  return out;
}

}  // namespace gcsim::pipeline
