// gcsim mpirun: runs an MPI program built with gcsim-mpicc on N simulated nodes, one rank per node,
// registered from the MPI layer's own folder (the gcsim command names no application).
#include <cstdio>
#include <string>

#include "apps/mpi/app/mpirun_options.hpp"
#include "apps/mpi/app/rank_run.hpp"
#include "apps/mpi/app/run_fields.hpp"
#include "apps/mpi/app/sweep_mpi_command.hpp"
#include "apps/mpi/app/run_computing.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::mpi_layer::app {
namespace {

void run_mpirun(const MpirunOptions& o) {
  parix::RunOptions run = pipeline::run_options(o.machine, o.np);
  run.simulation.config.fiber_stack_bytes = o.stack_bytes;
  if (o.ranks_per_node > 1) {  // rank r on node r / K
    for (int r = 0; r < o.np; ++r) run.simulation.placement.push_back(r / o.ranks_per_node);
  }
  pipeline::check_machine_outputs(o.machine);
  RunComputing computing(o, run.simulation.config);
  RankRun ran;
  try {
    ran = run_ranks(o, run, computing.settings, false, CopiesAtEnd::leave_to_exit);  // the process's one run
  } catch (const parix::host::Interrupted& x) {  // after the ranks' output: the trace and the JSON are kept
    pipeline::report_interrupted_run(x.partial(), o.machine);
    throw;
  }
  computing.print();
  nlohmann::json fields = run_fields(o, ran.result.config_name);
  fields["compute"] = computing.to_json();
  pipeline::report_run(ran.result, o.machine, fields);
  if (ran.failed_rank >= 0) throw pipeline::ExitStatus{ran.statuses[static_cast<std::size_t>(ran.failed_rank)]};
}

void add_mpirun(pipeline::CommandGroups& g) {
  CLI::App* cmd = g.app->add_subcommand("mpirun", mpirun_summary());
  cmd->prefix_command();
  cmd->allow_extras();
  cmd->footer(mpirun_usage());
  cmd->callback([cmd] {
    const MpirunOptions o = parse_mpirun_options(cmd->remaining());
    if (o.help) {
      std::printf("%s", mpirun_usage().c_str());
      return;
    }
    run_mpirun(o);
  });
}

const pipeline::CommandFamilyRegistrar registrar{{.name = "mpi", .commands = [](pipeline::CommandGroups& g) {
                                                    add_mpirun(g);
                                                    add_sweep_mpi(g);
                                                  }}};

}  // namespace
}  // namespace gcsim::mpi_layer::app
