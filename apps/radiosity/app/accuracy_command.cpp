// gcsim accuracy radiosity: what accuracy costs, as four tables (form factors against closed forms,
// radiosities against Gauss-Seidel per energy threshold, hierarchical against fixed hemicubes).
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/radiosity/accuracy.hpp"
#include "apps/radiosity/app/commands.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/near_field_accuracy.hpp"
#include "machine/machine_config.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::radiosity::app {

namespace {

struct AccuracyFlags {
  std::vector<std::string> resolutions{"16", "32", "64", "128", "256", "512"};
  std::vector<std::string> thresholds{"0.9", "0.95", "0.99", "0.995", "0.999", "0.9999"};
  std::vector<std::string> levels{"1", "2", "3", "4"};
  int hierarchical_hemicube = 256;
  std::string scene = "cornell", config;
  int hemicube = 64;
  int shooters = 2;
  std::vector<std::string> near_field{"1", "0.5", "0.25"};
  int near_field_hemicube = 256;
  int near_field_samples = 8;
  std::string json;
};

// The rows so far (JSON), the table being measured and the progress line: an interrupted run
// writes what it finished.
struct AccuracyReport {
  nlohmann::json j = nlohmann::json::object();
  pipeline::ProgressLine progress;
  int done = 0;
  std::string table;  // "form_factors", "energy", "hierarchical" or "near_field"
  AccuracyReport(int rows) : progress("accuracy radiosity", rows) {}
  // Before a row goes to stdout; the line is drawn again after it.
  void row_printed(const std::string& detail) {
    std::fflush(stdout);
    progress.update(++done, detail);
  }
  void start(const std::string& name, const std::string& detail) {
    std::fflush(stdout);  // the table's header, before its first row takes a while
    table = name;
    progress.update(done, detail);
  }
};

void print_form_factor_table(const std::vector<int>& res, const machine::MachineConfig& m, AccuracyReport& rep) {
  fmt::print("1. hemicube form factors against closed forms (relative errors)\n");
  fmt::print("{:<46} {:>5} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10} {:>8}\n", "case", "res", "point", "exact", "error",
             "area", "exact", "error", "sim_s", "wall_s");
  rep.start("form_factors", "table 1");
  form_factor_accuracy(res, m, [&](const FormFactorAccuracy& a) {
    rep.progress.clear();
    fmt::print("{:<46} {:>5} {:>9.6f} {:>9.6f} {:>9.2e} {:>9.6f} {:>9.6f} {:>9.2e} {:>10.4f} {:>8.3f}\n",
               to_string(a.form_factor_case), a.resolution, a.hemicube_point, a.exact_point, a.point_error(), a.hemicube_area,
               a.exact_area, a.area_error(), a.simulated_seconds, a.wall_seconds);
    rep.j["form_factors"].push_back({{"case", to_string(a.form_factor_case)}, {"resolution", a.resolution},
                                     {"point", a.hemicube_point}, {"exact_point", a.exact_point},
                                     {"point_error", a.point_error()}, {"area", a.hemicube_area}, {"exact_area", a.exact_area},
                                     {"area_error", a.area_error()}, {"simulated_s", a.simulated_seconds},
                                     {"wall_s", a.wall_seconds}});
    rep.row_printed(fmt::format("table 1, {} at {}", to_string(a.form_factor_case), a.resolution));
  });
}

void print_energy_table(const Scene& scene, const SolverOptions& so, const std::vector<double>& th,
                        const machine::MachineConfig& m, AccuracyReport& rep) {
  fmt::print("\n2. {} radiosities against converged Gauss-Seidel (hemicube {}, K {}); errors relative to the mean radiosity\n",
             scene.name, so.hemicube.resolution, so.shooters);
  fmt::print("{:>9} {:>6} {:>10} {:>10} {:>10} {:>8}\n", "energy", "loops", "rms_err", "max_err", "sim_s", "wall_s");
  rep.start("energy", "table 2, Gauss-Seidel reference and progressive run");
  const auto ea = energy_accuracy(scene, so, th, m, [&](const EnergyAccuracy& a) {
    rep.progress.clear();
    fmt::print("{:>9} {:>6} {:>10.3e} {:>10.3e} {:>10.3f} {:>8.3f}\n", a.threshold, a.steps, a.rms_relative_error,
               a.max_relative_error, a.simulated_seconds, a.wall_seconds);
    rep.j["energy"].push_back({{"threshold", a.threshold}, {"loops", a.steps}, {"rms_error", a.rms_relative_error},
                               {"max_error", a.max_relative_error}, {"simulated_s", a.simulated_seconds},
                               {"wall_s", a.wall_seconds}});
    rep.row_printed(fmt::format("table 2, energy {} reached", a.threshold));
  });
  rep.done += int(th.size() - ea.size());  // thresholds never reached are rows too
  if (ea.size() < th.size()) fmt::print("(thresholds above {} were not reached)\n", ea.empty() ? 0.0 : ea.back().threshold);
}

void print_hierarchical_table(const Scene& scene, SolverOptions ho, int resolution, const std::vector<int>& lv,
                              const machine::MachineConfig& m, AccuracyReport& rep) {
  ho.hemicube.resolution = resolution;
  fmt::print("\n3. {} hierarchical hemicube against the fixed hemicube {} (energy {}, K {}); errors relative to the mean\n",
             scene.name, resolution, ho.energy, ho.shooters);
  fmt::print("{:>7} {:>6} {:>10} {:>10} {:>10} {:>8}\n", "levels", "loops", "rms_err", "max_err", "sim_s", "wall_s");
  rep.start("hierarchical", "table 3, fixed hemicube");
  hierarchical_accuracy(scene, ho, lv, m, [&](const HierarchicalAccuracy& a) {
    rep.progress.clear();
    fmt::print("{:>7} {:>6} {:>10.3e} {:>10.3e} {:>10.3f} {:>8.3f}\n",
               a.levels == 0 ? std::string("fixed") : fmt::format("{}", a.levels), a.steps, a.rms_relative_error,
               a.max_relative_error, a.simulated_seconds, a.wall_seconds);
    rep.j["hierarchical"].push_back({{"levels", a.levels}, {"loops", a.steps}, {"rms_error", a.rms_relative_error},
                                     {"max_error", a.max_relative_error}, {"simulated_s", a.simulated_seconds},
                                     {"wall_s", a.wall_seconds}});
    rep.row_printed(fmt::format("table 3, {} levels done", a.levels));
  });
}

void check_levels(const std::vector<int>& lv, int resolution) {
  for (int l : lv)
    if (resolution % (2 << l) != 0 || resolution / (1 << l) < 8)
      throw std::invalid_argument(fmt::format("--levels: {} levels need a hemicube resolution that is a multiple of {} and at least {}",
                                              l, 2 << l, 8 << l));
}

// SIGINT/SIGTERM: the rows finished so far go to --json, marked, with the table that was running.
void report_interrupted(const AccuracyFlags& f, AccuracyReport& rep) {
  rep.progress.clear();
  fmt::print("\ninterrupted during the {} table; {} rows finished\n", rep.table, rep.done);
  rep.j["interrupted"] = true;
  rep.j["interrupted_table"] = rep.table;
  if (!f.json.empty()) pipeline::write_json_file(f.json, rep.j);
}

// Table 4's ratios, checked before any table runs.
std::vector<double> near_field_ratios(const AccuracyFlags& f) {
  if (pipeline::list_is_empty(f.near_field)) return {};
  const std::vector<double> ratios = pipeline::parse_double_list(f.near_field, "--near-field");
  for (double r : ratios)
    if (!(r > 0)) throw std::invalid_argument(fmt::format("--near-field: ratio {} must be positive", r));
  HemicubeOptions check;
  check.resolution = f.near_field_hemicube;
  check.max_shooter_samples = f.near_field_samples;
  check_hemicube_options(check);
  return ratios;
}

void print_near_field_table(const Scene& scene, SolverOptions no, const AccuracyFlags& f, const std::vector<double>& ratios,
                            const machine::MachineConfig& m, AccuracyReport& rep) {
  no.hemicube.resolution = f.near_field_hemicube;
  no.hemicube.max_shooter_samples = f.near_field_samples;
  fmt::print("\n4. near field: a shooter splits until each part is at most ratio x its distance to the nearest\n"
             "   receiver, up to {} x {} parts (hemicube {}). facing: receiver of two facing unit squares 1 apart,\n"
             "   rho 0.5 (closed form {:.5f}); furnace: closed box rho 0.5, E 1, 4x4 patches of 2x2 elements,\n"
             "   extreme elements against B = 2; cost: {} on one node at energy {}, K {}\n",
             f.near_field_samples, f.near_field_samples, f.near_field_hemicube, 0.5 * parallel_rectangles_form_factor(1, 1, 1),
             scene.name, no.energy, no.shooters);
  fmt::print("{:>9} {:>10} {:>10} {:>11} {:>11} {:>6} {:>10} {:>8}\n", "ratio", "facing_B", "facing_err", "furnace_min",
             "furnace_max", "loops", "sim_s", "wall_s");
  rep.start("near_field", "table 4");
  near_field_accuracy(scene, no, ratios, m, [&](const NearFieldAccuracy& a) {
    rep.progress.clear();
    fmt::print("{:>9} {:>10.5f} {:>+9.2f}% {:>+10.2f}% {:>+10.2f}% {:>6} {:>10.3f} {:>8.3f}\n",
               a.ratio == 0 ? std::string("1 point") : fmt::format("{}", a.ratio), a.facing_b, 100 * a.facing_error(),
               100 * a.furnace_min_error(), 100 * a.furnace_max_error(), a.scene_steps, a.scene_simulated_seconds,
               a.wall_seconds);
    rep.j["near_field"].push_back({{"ratio", a.ratio}, {"max_samples_per_side", a.max_samples_per_side},
                                   {"facing_b", a.facing_b}, {"facing_exact", a.facing_exact},
                                   {"facing_error", a.facing_error()}, {"furnace_min", a.furnace_min},
                                   {"furnace_max", a.furnace_max}, {"scene_loops", a.scene_steps},
                                   {"simulated_s", a.scene_simulated_seconds}, {"wall_s", a.wall_seconds}});
    rep.row_printed(a.ratio == 0 ? std::string("table 4, one point done") : fmt::format("table 4, ratio {} done", a.ratio));
  });
}

void run_accuracy(const AccuracyFlags& f) {
  const machine::MachineConfig m = f.config.empty() ? machine::default_machine_config() : machine::load_machine_config(f.config);
  const std::vector<int> res = pipeline::parse_int_list(f.resolutions, "--resolutions");
  for (int r : res)
    if (r % 2 != 0 || r < 8) throw std::invalid_argument(fmt::format("--resolutions: {} must be even and at least 8", r));
  const std::vector<double> th = pipeline::parse_double_list(f.thresholds, "--thresholds");
  for (std::size_t i = 0; i < th.size(); ++i)
    if (th[i] <= 0 || th[i] >= 1 || (i > 0 && th[i] <= th[i - 1]))
      throw std::invalid_argument("--thresholds: expected ascending fractions in (0, 1)");
  const std::vector<int> lv = pipeline::list_is_empty(f.levels) ? std::vector<int>{} : pipeline::parse_int_list(f.levels, "--levels");
  check_levels(lv, f.hierarchical_hemicube);
  if (!f.json.empty()) pipeline::check_writable(f.json, "--json");
  const int table3_rows = lv.empty() ? 0 : int(lv.size()) + 1;
  const std::vector<double> ratios = near_field_ratios(f);
  const int table4_rows = f.near_field.empty() ? 0 : int(ratios.size()) + 1;
  AccuracyReport rep(int(3 * res.size() + th.size()) + table3_rows + table4_rows);
  try {
    print_form_factor_table(res, m, rep);
    const Scene scene = flatten(load_scene_world(f.scene));
    SolverOptions so;
    so.hemicube.resolution = f.hemicube;
    so.shooters = f.shooters;
    print_energy_table(scene, so, th, m, rep);
    if (!lv.empty()) print_hierarchical_table(scene, so, f.hierarchical_hemicube, lv, m, rep);
    if (!f.near_field.empty()) print_near_field_table(scene, so, f, ratios, m, rep);
  } catch (const parix::host::Interrupted&) {
    report_interrupted(f, rep);
    throw;
  }
  rep.progress.clear();
  if (!f.json.empty()) pipeline::write_json_file(f.json, rep.j);
}

}  // namespace

void add_accuracy_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<AccuracyFlags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "radiosity",
      "What accuracy costs in radiosity, as four tables.\n"
      "1. Hemicube form factors against closed forms, per resolution: from the centre of a unit square\n"
      "   to the parallel unit square at distance 1 and to the perpendicular unit square sharing an edge,\n"
      "   and from a small patch to a disc (r = 1 at h = 1: F = r^2/(h^2 + r^2)). 'point' is one hemicube\n"
      "   at the centre against the exact differential form factor; 'area' is the mean of 8 x 8\n"
      "   hemicubes against the exact area-to-area form factor (for the disc, polygon of 256 sides:\n"
      "   point is exact for the polygon, area is the ideal disc).\n"
      "2. Radiosities of a scene after shooting a fraction of the energy, against the converged\n"
      "   Gauss-Seidel solution with the same form factors.\n"
      "3. The hierarchical hemicube (4.5) against the fixed one of the same resolution, per number of\n"
      "   levels: what adaptive sampling saves, and the radiosity error it costs.\n"
      "4. The near field: a shooter near its receivers shoots from several points of its area (run's\n"
      "   --near-field-ratio and --near-field-samples). Per ratio: the error on two facing unit squares\n"
      "   and on every element of a closed furnace box (closed forms), and the scene's time on one node.\n"
      "Times are simulated seconds on one node of the machine (counted operations) and host wall seconds.");
  pipeline::add_list_option(cmd, "--resolutions", f->resolutions, "Hemicube resolutions for table 1")->capture_default_str();
  pipeline::add_list_option(cmd, "--thresholds", f->thresholds, "Energy thresholds for table 2, ascending")->capture_default_str();
  cmd->add_option("--scene", f->scene, "Scene for tables 2 and 3")->capture_default_str();
  pipeline::add_list_option(cmd, "--levels", f->levels, "Hierarchical levels for table 3 (empty: skip the table)")->capture_default_str();
  cmd->add_option("--hierarchical-hemicube", f->hierarchical_hemicube, "Hemicube resolution for table 3")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--hemicube", f->hemicube, "Hemicube resolution for table 2")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--shooters", f->shooters, "Shooters per loop for table 2")->check(CLI::Range(1, 1 << 20))->capture_default_str();
  pipeline::add_list_option(cmd, "--near-field", f->near_field,
                  "Near-field ratios for table 4 (run's --near-field-ratio; empty: skip the table)")
      ->capture_default_str();
  cmd->add_option("--near-field-samples", f->near_field_samples, "Cap on the parts per side in table 4")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32}))
      ->capture_default_str();
  cmd->add_option("--near-field-hemicube", f->near_field_hemicube, "Hemicube resolution for table 4")
      ->check(CLI::Range(16, 4096))
      ->capture_default_str();
  pipeline::add_config_option(cmd, f->config, "Machine file whose [ops] costs turn counts into seconds");
  pipeline::add_json_option(cmd, f->json, "every table");
  cmd->callback([f] { run_accuracy(*f); });
}

}  // namespace gcsim::radiosity::app
