#include "apps/mpi/app/sweep_mpi_command.hpp"

#include <cstdio>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "apps/mpi/app/rank_run.hpp"
#include "apps/mpi/app/run_computing.hpp"
#include "apps/mpi/app/sweep_mpi_options.hpp"
#include "apps/mpi/app/sweep_mpi_table.hpp"
#include "apps/pipeline/experiment.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/run_provenance.hpp"
#include "machine/machine_config.hpp"
#include "machine/output_file.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::mpi_layer::app {
namespace {

// One point's machine and node count, as `gcsim mpirun -np N [--config F] [--model M]` builds it.
parix::RunOptions point_options(const SweepMpiOptions& o, const SweepMachine& m, int nodes) {
  pipeline::MachineOptions mo;
  mo.config = m.file;
  mo.model = o.run.machine.model;
  mo.nodes = nodes;
  parix::RunOptions run = pipeline::run_options(mo, nodes);
  if (m.published) {
    run.simulation.config = machine::with_nodes(machine::published_machine_config(), nodes);
    if (!mo.model.empty()) run.simulation.config.network_model = mo.model;
  }
  run.simulation.config.fiber_stack_bytes = o.run.stack_bytes;
  return run;
}

std::unique_ptr<pipeline::Outcome> run_point(const SweepMpiOptions& o, const SweepMachine& m, int nodes) {
  MpirunOptions point = o.run;
  point.np = nodes;
  point.machine.nodes = nodes;
  const parix::RunOptions run = point_options(o, m, nodes);
  const RunComputing computing(point, run.simulation.config);
  const RankRun ran = run_ranks(point, run, computing.settings, true, CopiesAtEnd::unload);  // one of several runs
  if (ran.failed_rank >= 0) {
    throw pipeline::RunFailure(fmt::format("{} nodes on the {} machine: rank {} exited with status {}{}{}", nodes, m.label,
                                           ran.failed_rank, ran.statuses[static_cast<std::size_t>(ran.failed_rank)],
                                           ran.failed_stderr.empty() ? "" : "; its stderr:\n", ran.failed_stderr));
  }
  auto out = std::make_unique<pipeline::Outcome>();
  out->run = ran.result;
  return out;
}

// The CSV's first row, for the plot's title (traces/README.md, "Sweep CSV").
std::string sweep_comment(const SweepMpiOptions& o) {
  std::string command = o.run.program;
  for (const std::string& a : o.run.args) command += " " + a;
  std::string machines;
  for (const SweepMachine& m : o.machines) machines += (machines.empty() ? "" : " and ") + m.label;
  return fmt::format("# gcsim sweep mpi {}; machine GC-PowerPlus {}; model {}", command, machines,
                     o.run.machine.model.empty() ? "each machine's" : o.run.machine.model);
}

// One machine's table; rows go to the CSV as they finish, so an interrupted sweep keeps them.
void sweep_machine(const SweepMpiOptions& o, const SweepMachine& m, std::ofstream& csv, nlohmann::json& rows) {
  const std::unique_ptr<pipeline::SweepTable> table = mpi_sweep_table(m.label);
  fmt::print("machine   {} ({})\n", point_options(o, m, o.nodes.front()).simulation.config.name, m.label);
  table->print_header();
  double first_seconds = 0;
  for (std::size_t i = 0; i < o.nodes.size(); ++i) {
    const std::unique_ptr<pipeline::Outcome> out = run_point(o, m, o.nodes[i]);
    const double t = out->run.simulated_seconds();
    if (i == 0) first_seconds = t;
    if (i == 0 && t <= 0)
      fmt::print("note: {} nodes take no simulated time, so no speedup is measured against them (computation takes "
                 "time only where annotated with gcsim_mpi_compute, <gcsim/mpi_ext.h>)\n", o.nodes[i]);
    const pipeline::SweepRow row{o.nodes[i], *out, t > 0 ? first_seconds / t : 0.0, i == 0};
    table->print_row(row);
    std::fflush(stdout);
    if (csv.is_open()) csv << table->csv_row(row) << std::endl;
    rows.push_back(table->json_row(row));
  }
  table->print_footer();
}

void run_sweep(const SweepMpiOptions& o) {
  pipeline::check_writable(o.csv, "--csv");
  pipeline::check_writable(o.json, "--json");
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) throw pipeline::FileError("cannot write CSV file '" + o.csv + "'");
    csv << sweep_comment(o) << '\n' << mpi_sweep_table("")->csv_header() << '\n';
  }
  nlohmann::json rows = nlohmann::json::array();
  try {
    for (const SweepMachine& m : o.machines) sweep_machine(o, m, csv, rows);
  } catch (const parix::host::Interrupted& x) {
    fmt::print("interrupted at simulated time {:.6f} s; {} rows finished{}\n", x.partial().simulated_seconds(), rows.size(),
               o.csv.empty() ? "" : " (in " + o.csv + ")");
    throw;
  }
  if (!o.csv.empty()) fmt::print("csv  {}\n", o.csv);
  if (!o.json.empty()) {
    std::vector<std::string> outputs{o.json};
    if (!o.csv.empty()) outputs.push_back(o.csv);
    const std::string file = o.machines.size() == 1 ? o.machines.front().file : "";
    pipeline::write_json_file(o.json, {{"rows", rows}, {"provenance", pipeline::run_provenance(file, "", {}, outputs)}});
    fmt::print("json {}\n", o.json);
  }
  machine::close_checked(csv, o.csv, "CSV file");
}

}  // namespace

void add_sweep_mpi(pipeline::CommandGroups& g) {
  CLI::App* cmd = g.sweep->add_subcommand("mpi", sweep_mpi_summary());
  cmd->prefix_command();
  cmd->allow_extras();
  cmd->footer(sweep_mpi_usage());
  cmd->callback([cmd] {
    const SweepMpiOptions o = parse_sweep_mpi_options(cmd->remaining());
    if (o.help) {
      std::printf("%s", sweep_mpi_usage().c_str());
      return;
    }
    run_sweep(o);
  });
}

}  // namespace gcsim::mpi_layer::app
