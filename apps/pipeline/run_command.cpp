#include "apps/pipeline/run_command.hpp"

#include <memory>

#include "apps/pipeline/machine_options.hpp"

namespace gcsim::pipeline {

void add_run_command(CLI::App& run, const AppSpec& app) {
  auto machine = std::make_shared<MachineOptions>();
  CLI::App* cmd = run.add_subcommand(app.name, app.summary);
  add_machine_options(cmd, *machine);
  ExperimentFactory prepare = app.options(*cmd, Verb::run);
  if (!app.run_footer.empty()) cmd->footer(app.run_footer);
  const int default_nodes = app.default_nodes;
  cmd->callback([machine, prepare, default_nodes] {
    // The scene is loaded and every option checked before the run, so a typo costs no simulation.
    const std::unique_ptr<Experiment> e = prepare();
    const parix::RunOptions options = run_options(*machine, default_nodes);
    e->print_setup(options.simulation.nodes);
    const std::unique_ptr<Outcome> out = run_experiment(*e, options);
    nlohmann::json extra;
    e->report(*out, extra);
    report_run(out->run, *machine, extra);
  });
}

}  // namespace gcsim::pipeline
