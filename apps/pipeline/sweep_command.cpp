#include "apps/pipeline/sweep_command.hpp"

#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/ordered_parallel.hpp"
#include "apps/pipeline/sweep_table.hpp"

namespace gcsim::pipeline {

namespace {

struct SweepFlags {
  MachineOptions machine;  // --backend, --config and --model
  std::string nodes = "1,2,4,8,16,32,64";
  std::string csv, json;
  int jobs = int(std::max(1u, std::thread::hardware_concurrency()));
};

void add_sweep_options(CLI::App* cmd, SweepFlags& f) {
  add_machine_choice_options(cmd, f.machine);
  cmd->add_option("--nodes,--node-counts", f.nodes, "Comma-separated node counts")->capture_default_str();
  cmd->add_option("--csv", f.csv, "Write the table as CSV");
  cmd->add_option("--json", f.json, "Write every run's JSON summary");
  cmd->add_option("--jobs", f.jobs,
                  "Simulations run at once on host threads (default: the host's cores); the rows are the same "
                  "and in the same order whatever the number")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  for (const char* name : {"--nodes", "--csv", "--json", "--jobs"}) cmd->get_option(name)->group("Sweep");
}

// Receives the points in node-count order: speedup, printed row, CSV line, JSON.
struct RowWriter {
  SweepTable& table;
  std::ofstream& csv;
  nlohmann::json rows = nlohmann::json::array();
  double first_seconds = 0;
  int first_nodes = 0;

  void operator()(int nodes, const Outcome& out) {
    const double t = out.run.simulated_seconds();
    const bool first = first_nodes == 0;
    if (first) first_seconds = t, first_nodes = nodes;
    double base = first_seconds;
    if (table.speedup_base() == SpeedupBase::first_point_scaled) base *= first_nodes;
    const SweepRow row{nodes, out, t > 0 ? base / t : 0.0, first};  // 0: nothing to compare (no time)
    table.print_row(row);
    std::fflush(stdout);
    if (csv.is_open()) csv << table.csv_row(row) << '\n';
    rows.push_back(table.json_row(row));
  }
};

void run_sweep(const SweepFlags& f, const Experiment& e) {
  const std::vector<int> counts = parse_int_list(f.nodes, "--nodes");
  e.print_sweep_setup();
  const std::unique_ptr<SweepTable> table = e.sweep_table();
  table->print_header();
  std::ofstream csv;
  if (!f.csv.empty()) {
    csv.open(f.csv);
    if (!csv) throw std::runtime_error("cannot write CSV file '" + f.csv + "'");
    csv << table->csv_header() << '\n';
  }
  RowWriter writer{*table, csv};
  run_ordered<std::unique_ptr<Outcome>>(
      int(counts.size()), f.jobs,
      [&](int i) {
        MachineOptions point = f.machine;
        point.nodes = counts[i];
        return run_experiment(e, run_options(point, counts[i]));
      },
      [&](int i, std::unique_ptr<Outcome>& out) { writer(counts[i], *out); });
  table->print_footer();
  if (!f.csv.empty() && table->announce_files()) fmt::print("csv  {}\n", f.csv);
  if (!f.json.empty()) {
    write_json_file(f.json, table->json_document(std::move(writer.rows)));
    if (table->announce_files()) fmt::print("json {}\n", f.json);
  }
}

}  // namespace

void add_sweep_command(CLI::App& sweep, const AppSpec& app) {
  auto flags = std::make_shared<SweepFlags>();
  const std::string summary = !app.sweep_summary.empty()
                                  ? app.sweep_summary
                                  : "Run " + app.name + " for several node counts: simulated seconds, speedup over the "
                                                        "first count, communication seconds (mean per node) and wall seconds.";
  CLI::App* cmd = sweep.add_subcommand(app.name, summary);
  ExperimentFactory prepare = app.options(*cmd, Verb::sweep);
  add_sweep_options(cmd, *flags);
  if (!app.sweep_footer.empty()) cmd->footer(app.sweep_footer);
  cmd->callback([flags, prepare] {
    parse_int_list(flags->nodes, "--nodes");  // a bad list fails before the scene is loaded
    // Under mpirun the ranks are the machine: one node count per job, so a sweep is one mpirun per point.
    if (flags->machine.backend != "simulated")
      throw std::invalid_argument("--backend " + flags->machine.backend +
                                  ": a sweep needs the simulated backend (under MPI the node count is the number of "
                                  "ranks: run `mpirun -np N gcsim run ...` once per node count)");
    const std::unique_ptr<Experiment> e = prepare();
    run_sweep(*flags, *e);
  });
}

}  // namespace gcsim::pipeline
