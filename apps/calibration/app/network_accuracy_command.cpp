// gcsim accuracy network: what each network model's fidelity buys and costs. The thesis's tables are
// predicted under every model, each row giving the error against the measured figures next to the
// host time the model took.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/pipeline/csv_comment.hpp"
#include "apps/calibration/app/commands.hpp"
#include "apps/calibration/app/prediction_flags.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/progress.hpp"
#include "machine/network_registry.hpp"

namespace gcsim::calibration::app {

namespace {

using pipeline::write_json_file;

// Every registered model, as --models takes them by default.
std::vector<std::string> every_model() {
  std::vector<std::string> out;
  for (const std::string& m : machine::network_model_names()) out.push_back(m);
  return out;
}

struct NetworkAccuracyFlags {
  // Lists split at ',' by CLI11 (add_list_option).
  // The tables: the broadcast grid and the CORNELL sweeps.
  std::vector<std::string> models = every_model(), tables = {"4.6", "4.7", "4.3", "4.8"};
  std::string config, scene = "CORNELL", json, csv;
  PredictFlags predict;
};

// The tables with only `scene`'s column measured (the broadcast tables as they are).
std::vector<cal::MeasuredTable> one_scene(std::vector<cal::MeasuredTable> tables, const std::string& scene) {
  for (auto& t : tables) {
    if (t.id == "4.6" || t.id == "4.7") continue;
    const int keep = t.column_of(scene);
    if (keep < 0) throw std::invalid_argument("--scene: '" + scene + "' is not a column of table " + t.id);
    for (auto& row : t.values)
      for (std::size_t k = 0; k < row.size(); ++k)
        if (int(k) != keep) row[k] = cal::kNotMeasured;
  }
  return tables;
}

// One model's predictions of every table: its rows printed and added to j and csv. An interruption
// writes --json with the finished models' rows and is rethrown.
void compare_model(const NetworkAccuracyFlags& f, const std::string& model, const cal::MachineFile& file,
                   const std::vector<cal::MeasuredTable>& tables, const cal::Predictor& scenes,
                   pipeline::ProgressLine& progress, nlohmann::json& j, std::ofstream& csv) {
  PredictFlags pf = f.predict;
  pf.model = model;
  cal::Predictor predictor(settings(pf));
  predictor.share_scenes(scenes);
  predictor.on_run([&](int done, int total) {
    progress.update_fraction(total > 0 ? double(done) / total : 0.0, fmt::format("{}: {}/{} simulated runs", model, done, total));
  });
  const auto wall_start = std::chrono::steady_clock::now();
  std::exception_ptr interruption;
  const auto cells = cal::compare(tables, predictor.predict(tables, file.config(), &interruption));
  progress.clear();
  if (interruption) {  // the finished models' rows are kept; a model's partial tables would not compare
    fmt::print("interrupted during the {} model\n", model);
    j["interrupted"] = true;
    j["interrupted_model"] = model;
    if (!f.json.empty()) write_json_file(f.json, j);
    std::rethrow_exception(interruption);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  for (const auto& s : cal::summarize(cells)) {
    fmt::print("{:<9} {:<6} {:>6} {:>8.1f}% {:>8.1f}% {:>7}/{:<3} {:>9.2f}\n", model, s.table, s.cells, 100 * s.median_error,
               100 * s.max_error, s.within_15, s.cells, wall);
    j["rows"].push_back({{"model", model}, {"table", s.table}, {"cells", s.cells}, {"median_error", s.median_error},
                         {"max_error", s.max_error}, {"within_15", s.within_15}, {"wall_s", wall}});
    if (csv) csv << fmt::format("{},{},{:.6f},{:.6f},{},{},{:.4f}\n", model, s.table, s.median_error, s.max_error, s.within_15, s.cells, wall);
  }
  if (csv) csv.flush();  // an interruption keeps the finished models' rows
  std::fflush(stdout);
}

void run_network_accuracy(const NetworkAccuracyFlags& f) {
  pipeline::check_writable(f.json, "--json");
  pipeline::check_writable(f.csv, "--csv");
  const cal::MachineFile file(f.config);
  const std::vector<cal::MeasuredTable> tables = one_scene(cal::tables_from_specs(f.tables, "--tables"), f.scene);
  nlohmann::json j;
  std::ofstream csv;
  if (!f.csv.empty()) {
    csv.open(f.csv);
    if (!csv) throw std::runtime_error("cannot write CSV file '" + f.csv + "'");
    const std::string models = fmt::format("{}", fmt::join(f.models, " "));  // one series per model: the comment names them all
    csv << pipeline::csv_comment("accuracy network", file.config().name, "each table's", models) << '\n';
    csv << "model,table,median_error,max_error,within_15,cells,wall_s\n";
  }
  // The scenes are matched to table 4.2 once, before any model's clock starts: the host time a
  // model costs is its simulations'.
  cal::Predictor scenes(settings(f.predict));
  scenes.prepare(tables);
  fmt::print("{}", workload_lines(scenes, f.predict.energy, "workload  "));
  fmt::print("{:<9} {:<6} {:>6} {:>9} {:>9} {:>11} {:>9}\n", "model", "table", "cells", "median", "max", "within 15%", "wall_s");
  pipeline::ProgressLine progress("accuracy network", 0);
  for (const auto& model : f.models) compare_model(f, model, file, tables, scenes, progress, j, csv);
  fmt::print("wall_s: host seconds to predict all the tables under that model (--jobs {})\n", f.predict.jobs);
  if (!f.json.empty()) write_json_file(f.json, j);
}

}  // namespace

void add_network_accuracy_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<NetworkAccuracyFlags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "network",
      "What each network model's fidelity buys and costs: the thesis's tables predicted under\n" +
          pipeline::and_list(machine::network_model_names()) +
          ", with the error against the measured figures and the host time each\n"
          "model took (the broadcast grid of tables 4.6/4.7 and one scene's columns of 4.3/4.8).");
  pipeline::add_config_option(cmd, f->config);
  pipeline::add_list_option(cmd, "--models", f->models, "Network models to compare, comma-separated: " + pipeline::network_model_summaries())
      ->check(pipeline::each_network_model())
      ->capture_default_str();
  pipeline::add_list_option(cmd, "--tables", f->tables, "Tables, as for calibrate --fit")->capture_default_str();
  cmd->add_option("--scene", f->scene, "Radiosity tables: the scene column to predict (ROOM, PICROOM, CORNELL)")->capture_default_str();
  pipeline::add_json_option(cmd, f->json, "the comparison");
  cmd->add_option("--csv", f->csv, "Write model,table,median,max,within_15,cells,wall_s as CSV (gcsim plot draws error against time)");
  add_predict_options(cmd, f->predict);
  cmd->callback([f] {
    apply_preset(f->predict);
    run_network_accuracy(*f);
  });
}

}  // namespace gcsim::calibration::app
