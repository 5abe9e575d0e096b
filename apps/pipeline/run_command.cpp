#include "apps/pipeline/run_command.hpp"

#include <memory>
#include <string>

#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::pipeline {

void add_run_command(CLI::App& run, const AppSpec& app) {
  auto machine = std::make_shared<MachineOptions>();
  CLI::App* cmd = run.add_subcommand(app.name, app.summary);
  add_machine_options(cmd, *machine, std::to_string(app.default_nodes));
  ExperimentFactory prepare = app.options(*cmd, Verb::run);
  if (!app.run_footer.empty()) cmd->footer(app.run_footer);
  const int default_nodes = app.default_nodes;
  cmd->callback([machine, prepare, default_nodes] {
    // The scene is loaded and every option and output path checked before the run, so a typo
    // costs no simulation.
    const std::unique_ptr<Experiment> e = prepare();
    check_machine_outputs(*machine);
    e->check_outputs();
    const parix::RunOptions options = run_options(*machine, default_nodes);
    e->print_setup(options.simulation.config.nodes);
    std::unique_ptr<Outcome> out;
    nlohmann::json reached = nlohmann::json::object();
    try {
      out = run_experiment(*e, options, &reached);
    } catch (const parix::host::Interrupted& x) {
      report_interrupted_run(x.partial(), *machine, reached, e->run_inputs());
      throw;
    }
    nlohmann::json extra;
    e->report(*out, extra);
    const std::optional<std::string> missed = e->goal_missed(*out);
    if (missed) extra["goal_missed"] = *missed;
    report_run(out->run, *machine, extra, e->run_inputs());
    if (missed) throw RunFailure(*missed);
  });
}

}  // namespace gcsim::pipeline
