// gcsim validate: predict measured tables with a machine file and compare them cell by cell; the
// cells a fit used (the file's [calibration] section) are marked and left out of the summaries.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/calibration/app/commands.hpp"
#include "apps/calibration/app/prediction_flags.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/progress.hpp"

namespace gcsim::calibration::app {

namespace {

using pipeline::write_json_file;

struct ValidateFlags {
  std::vector<std::string> tables;  // split at ',' by CLI11 (add_list_option)
  std::string config, json, csv;
  PredictFlags predict;
};

// The tables to validate: those named, or every built-in table not wholly fitted; cells the fit
// used are marked.
std::vector<cal::MeasuredTable> validation_tables(const std::vector<std::string>& named, const machine::MachineConfig& c) {
  std::vector<cal::MeasuredTable> out;
  if (!named.empty()) return cal::tables_from_specs(named, "--tables");
  for (const auto& id : cal::thesis_table_ids()) {
    const bool wholly_fitted = std::find(c.calibrated_on.begin(), c.calibrated_on.end(), id) != c.calibrated_on.end();
    if (!wholly_fitted) out.push_back(cal::thesis_table(id));
  }
  return out;
}

void mark_fitted(std::vector<cal::CellComparison>& cells, const machine::MachineConfig& c) {
  for (const auto& spec : c.calibrated_on) {
    const cal::MeasuredTable fitted = cal::table_from_spec(spec);
    for (auto& cell : cells) {
      const int r = fitted.row_of(cell.nodes), k = fitted.column_of(cell.column);
      if (cell.table == fitted.id && r >= 0 && k >= 0 && !std::isnan(fitted.values[r][k])) cell.fitted = true;
    }
  }
}

// gcsim validate's run: the predictions, the comparison and the files it writes.
void run_validate(const ValidateFlags& f) {
  pipeline::check_writable(f.json, "--json");
  pipeline::check_writable(f.csv, "--csv");
  const cal::MachineFile file(f.config);
  const auto tables = validation_tables(f.tables, file.config());
  if (tables.empty()) throw std::invalid_argument("nothing to validate: every table was fitted (name some with --tables)");
  cal::Predictor predictor(settings(f.predict));
  std::string ids;
  for (const auto& t : tables) ids += (ids.empty() ? "" : ", ") + t.id;
  fmt::print("predicting table(s) {} with {} ...\n", ids, file.config().name);
  std::fflush(stdout);
  pipeline::ProgressLine progress("validate", 0);
  predictor.on_run([&](int done, int total) {
    progress.update_fraction(total > 0 ? double(done) / total : 0.0, fmt::format("{}/{} simulated runs", done, total));
  });
  std::exception_ptr interruption;
  auto cells = cal::compare(tables, predictor.predict(tables, file.config(), &interruption));
  progress.clear();
  // An interruption leaves the cells whose runs finished; the others are not predicted.
  std::erase_if(cells, [](const cal::CellComparison& c) { return std::isnan(c.predicted); });
  mark_fitted(cells, file.config());
  fmt::print("{}", workload_lines(predictor, f.predict.energy, "workload  "));
  cal::print_cells(cells, tables);
  const auto summaries = cal::summarize(cells);
  cal::print_summaries(summaries);
  if (interruption) fmt::print("\ninterrupted: {} cells predicted before it\n", cells.size());
  if (!f.csv.empty()) cal::write_csv(f.csv, cells, cells_comment("validate", file.config(), cells, f.predict.model));
  if (!f.json.empty()) {
    nlohmann::json j = cal::to_json(cells, summaries);
    for (const auto& [scene, m] : predictor.loop_matches())
      j["workload"][scene] = {{"reflectance_scale", m.scale}, {"loops", m.loops}, {"thesis_loops", m.thesis_loops},
                              {"loops_as_built", m.loops_as_built}};
    if (interruption) j["interrupted"] = true;
    write_json_file(f.json, j);
  }
  if (interruption) std::rethrow_exception(interruption);
}

}  // namespace

void add_validate_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<ValidateFlags>();
  CLI::App* cmd = g.app->add_subcommand(
      "validate",
      "Predict measured tables with a machine file and compare, cell by cell.\n\n"
      "By default every built-in thesis table (4.3-4.8) that the file's [calibration] section does not\n"
      "name as fitted; cells the fit used are marked and left out of the summaries. Per table: the\n"
      "largest and median relative error and the cells within 15 % and 25 %.");
  pipeline::add_config_option(cmd, f->config);
  pipeline::add_list_option(cmd, "--tables", f->tables, "Tables to predict, as for calibrate --fit; default: every table not fitted");
  pipeline::add_json_option(cmd, f->json, "every cell and the summaries");
  cmd->add_option("--csv", f->csv, "Write every cell as CSV (gcsim plot --calibration draws it)");
  add_predict_options(cmd, f->predict);
  cmd->callback([f] {
    apply_preset(f->predict);
    run_validate(*f);
  });
}

}  // namespace gcsim::calibration::app
