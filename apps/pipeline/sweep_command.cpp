#include "apps/pipeline/sweep_command.hpp"

#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "apps/common/ordered_parallel.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "machine/output_file.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/pipeline/sweep_table.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::pipeline {

namespace {

struct SweepFlags {
  MachineOptions machine;  // --backend, --config and --model
  std::vector<std::string> nodes{"1", "2", "4", "8", "16", "32", "64"};
  std::string csv, json;
  int jobs = int(std::max(1u, std::thread::hardware_concurrency()));
};

void add_sweep_options(CLI::App* cmd, SweepFlags& f) {
  add_machine_choice_options(cmd, f.machine);
  add_list_option(cmd, "--nodes,--node-counts", f.nodes, "Comma-separated node counts")->capture_default_str();
  cmd->add_option("--csv", f.csv, "Write the table as CSV");
  add_json_option(cmd, f.json, "every run's summary");
  cmd->add_option("--jobs", f.jobs,
                  "Simulations run at once on host threads (default: the host's cores); the rows are the same "
                  "and in the same order whatever the number")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  for (const char* name : {"--nodes", "--csv", "--json", "--jobs"}) cmd->get_option(name)->group("Sweep");
}

// Receives the points in node-count order: speedup, printed row, CSV line (flushed, so an
// interrupted or killed sweep keeps every finished row), JSON.
struct RowWriter {
  RowWriter(SweepTable& t, std::ofstream& c, const Experiment& e) : table(t), csv(c), experiment(e) {}
  SweepTable& table;
  std::ofstream& csv;
  const Experiment& experiment;
  nlohmann::json rows = nlohmann::json::array();
  std::vector<int> finished;
  std::vector<std::string> missed;  // points that did not reach their goal
  double first_seconds = 0;
  int first_nodes = 0;

  void operator()(int nodes, const Outcome& out) {
    finished.push_back(nodes);
    if (const auto why = experiment.goal_missed(out)) missed.push_back(fmt::format("{} nodes: {}", nodes, *why));
    const double t = out.run.simulated_seconds();
    const bool first = first_nodes == 0;
    if (first) first_seconds = t, first_nodes = nodes;
    double base = first_seconds;
    if (table.speedup_base() == SpeedupBase::first_point_scaled) base *= first_nodes;
    const SweepRow row{nodes, out, t > 0 ? base / t : 0.0, first};  // 0: nothing to compare (no time)
    table.print_row(row);
    std::fflush(stdout);
    if (csv.is_open()) csv << table.csv_row(row) << std::endl;
    rows.push_back(table.json_row(row));
  }
};

// The document --json writes, with the sweep's provenance (run_provenance.hpp) beside the rows.
nlohmann::json sweep_document(const SweepFlags& f, const Experiment& e, const std::string& machine, nlohmann::json doc) {
  if (!doc.is_object()) doc = nlohmann::json{{"rows", std::move(doc)}};
  std::vector<std::string> outputs{f.json};
  if (!f.csv.empty()) outputs.push_back(f.csv);
  doc["provenance"] = run_provenance(f.machine.config, machine, e.run_inputs(), outputs);
  return doc;
}

// A sweep stopped by SIGINT/SIGTERM: the CSV already holds the finished rows; --json gets them
// with where the sweep stopped.
void report_interrupted_sweep(const SweepFlags& f, const Experiment& e, const std::vector<int>& counts,
                              const SweepTable& table, RowWriter& writer, const parix::RunResult& partial) {
  const std::size_t done = writer.finished.size();
  const int at = done < counts.size() ? counts[done] : 0;
  fmt::print("interrupted during the {}-node point at simulated time {:.6f} s; {} of {} points finished\n", at,
             partial.simulated_seconds(), done, counts.size());
  if (!f.csv.empty()) fmt::print("csv  {} (the finished rows)\n", f.csv);
  if (f.json.empty()) return;
  nlohmann::json doc = sweep_document(f, e, partial.config_name, table.json_document(std::move(writer.rows)));
  doc["interrupted"] = true;
  doc["finished_nodes"] = writer.finished;
  doc["interrupted_nodes"] = at;
  doc["interrupted_simulated_s"] = partial.simulated_seconds();
  write_json_file(f.json, doc);
  fmt::print("json {}\n", f.json);
}

// The CSV's first row, for the plot's title (traces/README.md, "Sweep CSV"); readers skip '#' rows.
std::string sweep_comment(const std::string& app, const std::string& scene, const MachineOptions& m, int nodes) {
  const parix::SimulationOptions s = simulation_options(m, nodes);
  std::string line = "# gcsim sweep " + app;
  if (!scene.empty()) line += "; scene " + scene;
  return line + fmt::format("; machine {}; model {}", s.config.name, s.config.network_model);
}

void run_sweep(const SweepFlags& f, const Experiment& e, const std::string& app) {
  const std::vector<int> counts = parse_int_list(f.nodes, "--nodes");
  check_writable(f.csv, "--csv");
  check_writable(f.json, "--json");
  const std::string machine = simulation_options(f.machine, counts.front()).config.name;
  fmt::print("machine   {}\n", machine);  // which GC, by name
  e.print_sweep_setup();
  const std::unique_ptr<SweepTable> table = e.sweep_table();
  table->print_header();
  std::ofstream csv;
  if (!f.csv.empty()) {
    csv.open(f.csv);
    if (!csv) throw FileError("cannot write CSV file '" + f.csv + "'");
    csv << sweep_comment(app, table->scene(), f.machine, counts[0]) << '\n' << table->csv_header() << '\n';
  }
  RowWriter writer{*table, csv, e};
  ProgressLine progress("sweep", int(counts.size()));
  progress.update(0, fmt::format("running {} nodes", counts[0]));
  try {
    apps::run_ordered<std::unique_ptr<Outcome>>(
        int(counts.size()), f.jobs,
        [&](int i) {
          MachineOptions point = f.machine;
          point.nodes = counts[i];
          return run_experiment(e, run_options(point, counts[i]));
        },
        [&](int i, std::unique_ptr<Outcome>& out) {
          progress.clear();
          writer(counts[i], *out);
          if (i + 1 < int(counts.size())) progress.update(i + 1, fmt::format("running {} nodes", counts[i + 1]));
        });
  } catch (const parix::host::Interrupted& x) {
    progress.clear();
    report_interrupted_sweep(f, e, counts, *table, writer, x.partial());
    throw;
  }
  progress.clear();
  table->print_footer();
  if (!f.csv.empty() && table->announce_files()) fmt::print("csv  {}\n", f.csv);
  if (!f.json.empty()) {
    write_json_file(f.json, sweep_document(f, e, machine, table->json_document(std::move(writer.rows))));
    if (table->announce_files()) fmt::print("json {}\n", f.json);
  }
  machine::close_checked(csv, f.csv, "CSV file");  // after the JSON, which a full CSV disk must not cost
  if (!writer.missed.empty()) {
    std::string why;
    for (const std::string& m : writer.missed) why += "\n  " + m;
    throw RunFailure(fmt::format("{} of {} points did not reach their goal:{}", writer.missed.size(), counts.size(), why));
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
  cmd->callback([flags, prepare, name = app.name] {
    parse_int_list(flags->nodes, "--nodes");  // a bad list fails before the scene is loaded
    // Under mpirun the ranks are the machine: one node count per job, so a sweep is one mpirun per point.
    if (flags->machine.backend != "simulated")
      throw std::invalid_argument("--backend " + flags->machine.backend +
                                  ": a sweep needs the simulated backend (under MPI the node count is the number of "
                                  "ranks: run `mpirun -np N gcsim run ...` once per node count)");
    const std::unique_ptr<Experiment> e = prepare();
    run_sweep(*flags, *e, name);
  });
}

}  // namespace gcsim::pipeline
