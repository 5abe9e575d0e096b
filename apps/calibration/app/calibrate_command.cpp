// gcsim calibrate: fit free keys of a machine file to measured tables by least squares, and write
// the fitted file (or, when interrupted, the best trial so far, marked as not a fit).
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/calibration/app/commands.hpp"
#include "apps/calibration/app/prediction_flags.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/progress.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::calibration::app {

namespace {

using pipeline::write_json_file;

// The fit's trials as they finish: the best so far (what an interruption leaves) and a progress
// line on a terminal (the runs of the current trial, the best sum of squared errors).
struct FitProgress {
  pipeline::ProgressLine line{"calibrate", 0};
  std::optional<cal::CalibrationTrial> best;
  int trials = 0;
  void trial(const cal::CalibrationTrial& t) {
    trials = t.number;
    if (!best || t.cost < best->cost) best = t;
  }
  void run(int done, int total) {
    line.update_fraction(total > 0 ? double(done) / total : 0.0,
                         best ? fmt::format("trial {}: run {}/{}; best so far {:.4g}", trials + 1, done, total, best->cost)
                              : fmt::format("trial {}: run {}/{}", trials + 1, done, total));
  }
};

// SIGINT/SIGTERM during the fit: --out gets the best trial's values, marked interrupted (not a
// fit), --json the trials done and the best so far.
void report_interrupted_fit(const cal::MachineFile& file, const std::string& specs, const std::string& out,
                            const std::string& json, const FitProgress& p, const std::string& command) {
  const cal::CalibrationTrial* best = p.best ? &*p.best : nullptr;
  fmt::print("\ninterrupted after {} trials{}\n", p.trials,
             best ? fmt::format("; the best so far (trial {}) has sum of squared errors {:.6g}", best->number, best->cost) : "");
  std::ofstream(out) << cal::interrupted_file_text(file, out, specs, best, p.trials, command);
  fmt::print("wrote {} (the best trial so far, not a fit)\n", out);
  if (json.empty()) return;
  nlohmann::json j{{"interrupted", true}, {"trials", p.trials}, {"converged", false}};
  if (best) {
    j["best"] = {{"trial", best->number}, {"cost", best->cost}};
    for (const auto& [key, value] : best->values)
      j["parameters"].push_back({{"key", key}, {"value", value}, {"initial", file.value(key)}});
  }
  write_json_file(json, j);
}

struct CalibrateFlags {
  std::vector<std::string> fit, free;  // split at ',' by CLI11 (add_list_option)
  std::string config, out, json, csv;
  PredictFlags predict;
};

// gcsim calibrate's run: the fit, its report, and the files it writes.
void run_calibrate(const CalibrateFlags& f) {
  for (const auto& [path, option] : {std::pair{f.out, "--out"}, {f.json, "--json"}, {f.csv, "--csv"}})
    pipeline::check_writable(path, option);  // before the fit's many runs
  const cal::MachineFile file(f.config);
  const std::vector<cal::MeasuredTable> tables = cal::tables_from_specs(f.fit);
  const std::vector<std::string>& free = f.free;
  for (const auto& k : free) file.check_free_key(k);
  cal::Predictor predictor(settings(f.predict));
  const std::string fit = fmt::format("{}", fmt::join(f.fit, ",")), free_text = fmt::format("{}", fmt::join(free, ","));
  const std::string command = "gcsim calibrate --fit " + fit + " --free " + free_text +
                              (f.config.empty() ? "" : " --config " + f.config) + non_default_flags(f.predict) +
                              " --out " + f.out;
  fmt::print("fitting {} to table(s) {} on {} ...\n", free_text, fit, file.source());
  std::fflush(stdout);
  FitProgress progress;
  predictor.on_run([&](int done, int total) { progress.run(done, total); });
  cal::CalibrationResult r;
  try {
    r = cal::calibrate(file, tables, free, predictor, [&](const cal::CalibrationTrial& t) { progress.trial(t); });
  } catch (const parix::host::Interrupted&) {
    progress.line.clear();
    report_interrupted_fit(file, fit, f.out, f.json, progress, command);
    throw;
  }
  progress.line.clear();
  fmt::print("{}", workload_lines(predictor, f.predict.energy, "workload  "));
  cal::print_cells(r.cells, tables);
  cal::print_summaries(cal::summarize(r.cells));
  fmt::print("\n{} after {} iterations ({} simulated runs){}\n", r.fit.converged ? "converged" : "NOT converged",
             r.fit.iterations, predictor.runs(), r.fit.converged ? "" : ": " + r.fit.reason);
  for (const auto& w : r.warnings) fmt::print(stderr, "gcsim: warning: {}\n", w);
  for (const auto& p : r.parameters)
    fmt::print("  {:<32} {:>12.6g} +- {:<10.2g} (was {:.6g})\n", p.key, p.value, p.sigma, p.initial);
  std::ofstream(f.out) << cal::fitted_file_text(file, f.out, f.fit, r, command,
                                                 workload_lines(predictor, f.predict.energy, "#   "));
  fmt::print("wrote {}\n", f.out);
  if (!f.csv.empty()) cal::write_csv(f.csv, r.cells, cells_comment("calibrate", file.config(), r.cells, f.predict.model));
  if (!f.json.empty()) {
    nlohmann::json j = cal::to_json(r.cells, cal::summarize(r.cells));
    for (const auto& p : r.parameters) j["parameters"].push_back({{"key", p.key}, {"value", p.value}, {"sigma", p.sigma}, {"initial", p.initial}});
    j["converged"] = r.fit.converged;
    write_json_file(f.json, j);
  }
  if (!r.fit.converged)
    throw pipeline::RunFailure(fmt::format("the fit did not converge after {} iterations; {} holds its last parameters",
                                           r.fit.iterations, f.out));
}

}  // namespace

void add_calibrate_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<CalibrateFlags>();
  CLI::App* cmd = g.app->add_subcommand(
      "calibrate",
      "Fit free parameters of a machine file to measured tables by least squares.\n\n"
      "Each measured figure is predicted by a simulated run of its experiment (tables 4.6/4.7: one\n"
      "all-node broadcast; 4.3/4.4/4.5/4.8: radiosity of ROOM, PICROOM, CORNELL to 99.9%); the fit\n"
      "minimises the sum of squared relative errors (GSL's Levenberg-Marquardt), each free key a\n"
      "positive factor of its value in the file. Prints every fitted cell, the fitted values with\n"
      "their standard errors, and writes a machine file that inherits --config and overrides only\n"
      "the fitted keys. Then `gcsim validate --config OUT` predicts the tables that were not fitted.");
  pipeline::add_list_option(cmd, "--fit", f->fit,
                  "Tables to fit, comma-separated: 4.6, 4.7, 4.3, 4.4, 4.5, 4.8 (the thesis's, built in); "
                  "TABLE@N+N keeps those node counts only (4.3@1: the 1-node figures), TABLE@NAME+NAME those columns "
                  "(4.3@1+8+CORNELL+PICROOM: two rows of two scenes); PATH.csv:TABLE is your "
                  "own figures in that table's layout (header nodes,<its columns>)")
      ->required();
  pipeline::add_list_option(cmd, "--free", f->free, "Keys to fit, comma-separated, as table.key: network.connect_base_us, ops.polygon_project, ...")
      ->required();
  pipeline::add_config_option(cmd, f->config, "Base machine file");
  cmd->add_option("--out", f->out, "Write the fitted machine file here")->required();
  pipeline::add_json_option(cmd, f->json, "the fitted values and every cell");
  cmd->add_option("--csv", f->csv, "Write every cell as CSV (gcsim plot --calibration draws it)");
  add_predict_options(cmd, f->predict);
  cmd->footer(
      "\n\nExample (the shipped configs/gc-powerplus-calibrated.toml):\n"
      "  cd configs && gcsim calibrate --fit 4.6,4.3@1+32+CORNELL+PICROOM \\\n"
      "      --free network.connect_base_us,network.connect_per_hop_us,network.link_bandwidth_mbps,"
      "ops.hemicube_pixel,ops.form_factor_merge \\\n"
      "      --config gc-powerplus-mechanisms.toml --out gc-powerplus-calibrated.toml");
  cmd->callback([f] {
    apply_preset(f->predict);
    run_calibrate(*f);
  });
}


}  // namespace gcsim::calibration::app
