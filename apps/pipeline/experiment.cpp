#include "apps/pipeline/experiment.hpp"

namespace gcsim::pipeline {

std::unique_ptr<Outcome> run_experiment(const Experiment& e, const parix::RunOptions& options) {
  const int nodes = options.simulation.nodes > 0 ? options.simulation.nodes : options.simulation.config.nodes;
  std::unique_ptr<Outcome> out = e.new_outcome(nodes);
  out->run = parix::run(options, e.program(*out));
  e.after_run(*out);
  return out;
}

}  // namespace gcsim::pipeline
