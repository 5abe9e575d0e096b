#pragma once
// The gcsim command's own families: machine commands (topo, bcast, bench ring, demo) and the trace
// commands (plot, report, paje). Applications are not listed here: they register themselves
// (apps/pipeline/app_registry.hpp) and the pipeline adds their commands.
#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/machine_options.hpp"

namespace gcsim::cli {

using pipeline::CommandGroups;
using pipeline::ExitStatus;
using pipeline::MachineOptions;
using pipeline::add_machine_choice_options;
using pipeline::add_machine_options;
using pipeline::report_run;
using pipeline::run_options;
using pipeline::simulation_options;
using pipeline::write_json_file;

void add_machine_commands(CommandGroups& g);
void add_trace_commands(CommandGroups& g);
// `gcsim help COMMAND...`: prints what `gcsim COMMAND... --help` prints.
void add_help_command(CLI::App* root);

}  // namespace gcsim::cli
