// gcsim calibrate, gcsim validate and gcsim accuracy network: fit a machine file to measured tables,
// predict the tables that played no part in the fit, and compare the network models. A command
// family registered from its own folder (apps/pipeline/app_registry.hpp), not an application.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "apps/calibration/calibration.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/progress.hpp"
#include "machine/network_registry.hpp"
#include "parix/interruption.hpp"

namespace gcsim::calibration {
namespace {

using pipeline::CommandGroups;
using pipeline::ExitStatus;
using pipeline::write_json_file;

namespace cal = gcsim::calibration;  // the library this family drives

struct PredictFlags {
  std::string model;
  int hemicube = 256;
  double energy = 0.999;
  std::string cell_assignment = "block";
  std::string side_faces = "full";
  std::string merge = "fixed-arrays";
  std::string ff_exchange = "together";
  std::string workload = "thesis-loops";
  std::string comm_time = "root";
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
};

void add_predict_options(CLI::App* cmd, PredictFlags& f) {
  cmd->add_option("--model", f.model, "Network model for every run; default: the machine file's")
      ->check(CLI::IsMember(machine::network_model_names()));
  cmd->add_option("--hemicube", f.hemicube, "Radiosity tables: hemicube resolution of the runs")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--energy", f.energy, "Radiosity tables: shot fraction at which a run stops (the thesis: 0.999)")
      ->check(CLI::Range(0.5, 0.99999))
      ->capture_default_str();
  cmd->add_option("--cell-assignment", f.cell_assignment,
                  "Radiosity tables: which hemicube cells each node computes: block (one region of the hemicube per "
                  "node, as the thesis's figure 4.1 draws it; fitted on 4.6 and two rows of 4.3 it predicts the other "
                  "radiosity cells better than cyclic: docs/calibration.md) or cyclic (`gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"cyclic", "block"}))
      ->capture_default_str();
  cmd->add_option("--side-faces", f.side_faces,
                  "Radiosity tables: the mesh the blocks are cut from: full (each side face a whole square whose "
                  "lower half, below the horizon, is empty: five equal faces; what the thesis's 2-, 4- and 8-node "
                  "rows imply together: docs/calibration.md) or half (`gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"half", "full"}))
      ->capture_default_str();
  cmd->add_option("--ff-merge", f.merge,
                  "Radiosity tables: how each node adds up the exchanged form factors: fixed-arrays (each of the N "
                  "parts as an array over every cell and 256 element slots, whatever the scene, counted as "
                  "communication: what tables 4.5 and 4.8 imply together, and 4.2 with 4.5 that it does not grow with "
                  "the elements; docs/calibration.md), whole-hemicube (the same over the scene's elements) or "
                  "own-cells (`gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"own-cells", "whole-hemicube", "fixed-arrays"}))
      ->capture_default_str();
  cmd->add_option("--ff-exchange", f.ff_exchange,
                  "Radiosity tables: together (2 exchanges per loop: the proposals, then every shooter's form factors "
                  "in one, the thesis's 4.4.1 \"two synchronizations per loop\"; docs/calibration.md) or per-shooter "
                  "(K + 1: each shooter's form factors on their own, `gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"per-shooter", "together"}))
      ->capture_default_str();
  cmd->add_option("--workload", f.workload,
                  "Radiosity tables: thesis-loops (each scene's reflectances scaled by the one factor that makes it "
                  "take table 4.2's loops at --energy, since a run's time is its loops times the machine's time per "
                  "loop: CORNELL as built takes 254 loops to 99.9 % where the thesis's took 302; docs/calibration.md) "
                  "or as-built (the scenes as `gcsim run radiosity` builds them)")
      ->check(CLI::IsMember({"thesis-loops", "as-built"}))
      ->capture_default_str();
  cmd->add_option("--comm-time", f.comm_time,
                  "Radiosity tables: whose communication time table 4.5 reports: root (processor 0, which every "
                  "exchange gathers to and scatters from; the thesis does not say whose time it printed: README, "
                  "Calibration) or mean (over the processors, as `gcsim run radiosity` prints it)")
      ->check(CLI::IsMember({"root", "mean"}))
      ->capture_default_str();
  cmd->add_option("--jobs", f.jobs, "Simulations run side by side on this many host threads")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
}

// The prediction flags that differ from their defaults, as a command line would give them, so that
// a fitted file's header names everything that reproduces the fit.
std::string non_default_flags(const PredictFlags& f) {
  const PredictFlags d;
  std::string out;
  if (f.model != d.model) out += " --model " + f.model;
  if (f.hemicube != d.hemicube) out += fmt::format(" --hemicube {}", f.hemicube);
  if (f.energy != d.energy) out += fmt::format(" --energy {}", f.energy);
  if (f.cell_assignment != d.cell_assignment) out += " --cell-assignment " + f.cell_assignment;
  if (f.side_faces != d.side_faces) out += " --side-faces " + f.side_faces;
  if (f.merge != d.merge) out += " --ff-merge " + f.merge;
  if (f.ff_exchange != d.ff_exchange) out += " --ff-exchange " + f.ff_exchange;
  if (f.workload != d.workload) out += " --workload " + f.workload;
  if (f.comm_time != d.comm_time) out += " --comm-time " + f.comm_time;
  return out;
}

cal::PredictionSettings settings(const PredictFlags& f) {
  cal::PredictionSettings s;
  s.model = f.model;
  s.hemicube = f.hemicube;
  s.energy = f.energy;
  s.cell_assignment = radiosity::parse_cell_assignment(f.cell_assignment);
  s.side_faces = radiosity::parse_side_faces(f.side_faces);
  s.merge = radiosity::parse_form_factor_merge(f.merge);
  s.ff_exchange = radiosity::parse_form_factor_exchange(f.ff_exchange);
  s.jobs = f.jobs;
  s.match_thesis_loops = f.workload == "thesis-loops";
  s.comm_time_of = cal::parse_comm_time_of(f.comm_time);
  return s;
}

// One line per scene matched to table 4.2 (--workload thesis-loops), each prefixed.
std::string workload_lines(const cal::Predictor& p, double energy, const std::string& prefix) {
  std::string out;
  for (const auto& [scene, m] : p.loop_matches())
    out += fmt::format("{}{}: every reflectance x{:.4f}, {} loops to {:g} % (table 4.2: {}; as built: {})\n", prefix, scene,
                       m.scale, m.loops, 100 * energy, m.thesis_loops, m.loops_as_built);
  return out;
}

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
  std::string fit, free, config, out, json, csv;
  PredictFlags predict;
};

// gcsim calibrate's run: the fit, its report, and the files it writes.
void run_calibrate(const CalibrateFlags& f) {
  for (const auto& [path, option] : {std::pair{f.out, "--out"}, {f.json, "--json"}, {f.csv, "--csv"}})
    pipeline::check_writable(path, option);  // before the fit's many runs
  const cal::MachineFile file(f.config);
  const std::vector<cal::MeasuredTable> tables = cal::tables_from_specs(f.fit);
  const std::vector<std::string> free = cal::split_list(f.free);
  for (const auto& k : free) file.check_free_key(k);
  cal::Predictor predictor(settings(f.predict));
  const std::string command = "gcsim calibrate --fit " + f.fit + " --free " + f.free +
                              (f.config.empty() ? "" : " --config " + f.config) + non_default_flags(f.predict) +
                              " --out " + f.out;
  fmt::print("fitting {} to table(s) {} on {} ...\n", f.free, f.fit, file.source());
  std::fflush(stdout);
  FitProgress progress;
  predictor.on_run([&](int done, int total) { progress.run(done, total); });
  cal::CalibrationResult r;
  try {
    r = cal::calibrate(file, tables, free, predictor, [&](const cal::CalibrationTrial& t) { progress.trial(t); });
  } catch (const parix::Interrupted&) {
    progress.line.clear();
    report_interrupted_fit(file, f.fit, f.out, f.json, progress, command);
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
  if (!f.csv.empty()) cal::write_csv(f.csv, r.cells);
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

void add_calibrate(CommandGroups& g) {
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
  cmd->add_option("--fit", f->fit,
                  "Tables to fit, comma-separated: 4.6, 4.7, 4.3, 4.4, 4.5, 4.8 (the thesis's, built in); "
                  "TABLE@N+N keeps those node counts only (4.3@1: the 1-node figures), TABLE@NAME+NAME those columns "
                  "(4.3@1+8+CORNELL+PICROOM: two rows of two scenes); PATH.csv:TABLE is your "
                  "own figures in that table's layout (header nodes,<its columns>)")
      ->required();
  cmd->add_option("--free", f->free, "Keys to fit, comma-separated, as table.key: network.connect_base_us, ops.polygon_project, ...")
      ->required();
  cmd->add_option("--config", f->config, "Base machine file; default: the built-in GC-PowerPlus as published")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", f->out, "Write the fitted machine file here")->required();
  cmd->add_option("--json", f->json, "Write the fitted values and every cell as JSON");
  cmd->add_option("--csv", f->csv, "Write every cell as CSV (gcsim plot --calibration draws it)");
  add_predict_options(cmd, f->predict);
  cmd->footer(
      "\n\nExample (the shipped configs/gc-powerplus-calibrated.toml):\n"
      "  cd configs && gcsim calibrate --fit 4.6,4.3@1+32+CORNELL+PICROOM \\\n"
      "      --free network.connect_base_us,network.connect_per_hop_us,network.link_bandwidth_mbps,"
      "ops.hemicube_pixel,ops.form_factor_merge \\\n"
      "      --config gc-powerplus-mechanisms.toml --out gc-powerplus-calibrated.toml");
  cmd->callback([f] { run_calibrate(*f); });
}

// The tables to validate: those named, or every built-in table not wholly fitted; cells the fit
// used are marked.
std::vector<cal::MeasuredTable> validation_tables(const std::string& named, const machine::MachineConfig& c) {
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

void add_validate(CommandGroups& g) {
  struct Flags {
    std::string config, tables, json, csv;
    PredictFlags predict;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.app->add_subcommand(
      "validate",
      "Predict measured tables with a machine file and compare, cell by cell.\n\n"
      "By default every built-in thesis table (4.3-4.8) that the file's [calibration] section does not\n"
      "name as fitted; cells the fit used are marked and left out of the summaries. Per table: the\n"
      "largest and median relative error and the cells within 15 % and 25 %.");
  cmd->add_option("--config", f->config, "Machine file; default: the built-in GC-PowerPlus as published")->check(CLI::ExistingFile);
  cmd->add_option("--tables", f->tables, "Tables to predict, as for calibrate --fit; default: every table not fitted");
  cmd->add_option("--json", f->json, "Write every cell and the summaries as JSON");
  cmd->add_option("--csv", f->csv, "Write every cell as CSV (gcsim plot --calibration draws it)");
  add_predict_options(cmd, f->predict);
  cmd->callback([f] {
    pipeline::check_writable(f->json, "--json");
    pipeline::check_writable(f->csv, "--csv");
    const cal::MachineFile file(f->config);
    const auto tables = validation_tables(f->tables, file.config());
    if (tables.empty()) throw std::invalid_argument("nothing to validate: every table was fitted (name some with --tables)");
    cal::Predictor predictor(settings(f->predict));
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
    fmt::print("{}", workload_lines(predictor, f->predict.energy, "workload  "));
    cal::print_cells(cells, tables);
    const auto summaries = cal::summarize(cells);
    cal::print_summaries(summaries);
    if (interruption) fmt::print("\ninterrupted: {} cells predicted before it\n", cells.size());
    if (!f->csv.empty()) cal::write_csv(f->csv, cells);
    if (!f->json.empty()) {
      nlohmann::json j = cal::to_json(cells, summaries);
      for (const auto& [scene, m] : predictor.loop_matches())
        j["workload"][scene] = {{"reflectance_scale", m.scale}, {"loops", m.loops}, {"thesis_loops", m.thesis_loops},
                                {"loops_as_built", m.loops_as_built}};
      if (interruption) j["interrupted"] = true;
      write_json_file(f->json, j);
    }
    if (interruption) std::rethrow_exception(interruption);
  });
}

// Table specs for `accuracy network`: the broadcast grid and the CORNELL sweeps.
constexpr const char* kNetworkAccuracyTables = "4.6,4.7,4.3,4.8";

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

void add_network_accuracy(CommandGroups& g) {
  struct Flags {
    std::string config, models = "analytic,flow,packet", tables = kNetworkAccuracyTables, scene = "CORNELL", json, csv;
    PredictFlags predict;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "network",
      "What each network model's fidelity buys and costs: the thesis's tables predicted under\n"
      "analytic, flow and packet, with the error against the measured figures and the host time each\n"
      "model took (the broadcast grid of tables 4.6/4.7 and one scene's columns of 4.3/4.8).");
  cmd->add_option("--config", f->config, "Machine file; default: the built-in GC-PowerPlus as published")->check(CLI::ExistingFile);
  cmd->add_option("--models", f->models, "Network models to compare")->capture_default_str();
  cmd->add_option("--tables", f->tables, "Tables, as for calibrate --fit")->capture_default_str();
  cmd->add_option("--scene", f->scene, "Radiosity tables: the scene column to predict (ROOM, PICROOM, CORNELL)")->capture_default_str();
  cmd->add_option("--json", f->json, "Write the comparison as JSON");
  cmd->add_option("--csv", f->csv, "Write model,table,median,max,within_15,cells,wall_s as CSV (gcsim plot draws error against time)");
  add_predict_options(cmd, f->predict);
  cmd->callback([f] {
    pipeline::check_writable(f->json, "--json");
    pipeline::check_writable(f->csv, "--csv");
    const cal::MachineFile file(f->config);
    const std::vector<cal::MeasuredTable> tables = one_scene(cal::tables_from_specs(f->tables, "--tables"), f->scene);
    nlohmann::json j;
    std::ofstream csv;
    if (!f->csv.empty()) {
      csv.open(f->csv);
      if (!csv) throw std::runtime_error("cannot write CSV file '" + f->csv + "'");
      csv << "model,table,median_error,max_error,within_15,cells,wall_s\n";
    }
    // The scenes are matched to table 4.2 once, before any model's clock starts: the host time a
    // model costs is its simulations'.
    cal::Predictor scenes(settings(f->predict));
    scenes.prepare(tables);
    fmt::print("{}", workload_lines(scenes, f->predict.energy, "workload  "));
    fmt::print("{:<9} {:<6} {:>6} {:>9} {:>9} {:>11} {:>9}\n", "model", "table", "cells", "median", "max", "within 15%", "wall_s");
    pipeline::ProgressLine progress("accuracy network", 0);
    for (const auto& model : cal::split_list(f->models)) {
      PredictFlags pf = f->predict;
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
        if (!f->json.empty()) write_json_file(f->json, j);
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
    fmt::print("wall_s: host seconds to predict all the tables under that model (--jobs {})\n", f->predict.jobs);
    if (!f->json.empty()) write_json_file(f->json, j);
  });
}

const pipeline::CommandFamilyRegistrar registrar{{.name = "calibration", .commands = [](CommandGroups& g) {
                                                    add_calibrate(g);
                                                    add_validate(g);
                                                    add_network_accuracy(g);
                                                  }}};

}  // namespace
}  // namespace gcsim::calibration
