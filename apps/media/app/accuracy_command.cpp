// gcsim accuracy media: RMSE of each estimator at equal simulated-time budgets against a high-sample
// reference on the same photon map, the noise spread, the grid's share, the photon count's effect,
// and each goal, stated as what it asks, as measured (accuracy.hpp).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/media/accuracy.hpp"
#include "apps/media/image_error.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/common/tone_map.hpp"
#include "apps/media/app/commands.hpp"
#include "apps/pipeline/csv_comment.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/progress.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::media::app {
namespace {

// The names of a list option, as CLI11 split them at ',', without empty ones.
std::vector<std::string> split_names(std::vector<std::string> names) {
  std::erase(names, std::string());
  return names;
}

struct AccuracyFlags {
  std::vector<std::string> scenes{"exp1", "exp2", "fog"};
  std::vector<std::string> estimators{"uniform", "transmittance", "radiance", "equiangular", "mis"};
  std::vector<std::string> budgets{"1", "2", "4", "8"}, photon_fractions{"0.25", "0.5", "1"};
  AccuracyOptions o;
  bool quick = false;
  std::string config, csv, json, images;
};

// DIR/media-SCENE-ESTIMATOR.png per estimator at the spread budget, DIR/media-SCENE-reference.png and
// DIR/media-SCENE-equal-time.png (uniform | transmittance | radiance side by side), all with the
// reference's exposure so they compare.
// The per-pixel relative std of the noise-spread renders, uniform | transmittance | radiance side by side
// on one grey scale (white: the largest 95th percentile of the three), so where each estimator's
// noise sits shows at a glance; unlit pixels are black.
void write_noise_maps(const std::string& file, const SceneAccuracy& a) {
  const Estimator side[] = {Estimator::uniform, Estimator::transmittance, Estimator::radiance};
  std::vector<const apps::Image*> maps;
  for (Estimator e : side)
    for (const auto& [me, map] : a.noise_maps)
      if (me == e) maps.push_back(&map);
  if (maps.size() != 3) return;
  double white = 0.0;
  for (const apps::Image* m : maps) {
    std::vector<double> lit;
    for (const glm::vec3& p : m->pixels())
      if (p.x > 0.0f) lit.push_back(p.x);
    if (!lit.empty()) white = std::max(white, quantile(lit, 0.95));
  }
  if (white <= 0.0) return;
  apps::Image strip(3 * a.width + 2 * 2, a.height);
  for (auto& px : strip.pixels()) px = glm::vec3(0.0f, 0.0f, 1.0f);  // blue gaps
  for (int i = 0; i < 3; ++i)
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x)
        strip.at(i * (a.width + 2) + x, y) = glm::vec3(std::min(1.0f, maps[i]->at(x, y).x / float(white)));
  apps::write_png(file, strip, 1.0f);
}

void write_images(const std::string& dir, const SceneAccuracy& a, double budget) {
  std::filesystem::create_directories(dir);
  const double exposure = apps::auto_exposure(a.reference);
  auto path = [&](const std::string& what) { return (std::filesystem::path(dir) / ("media-" + a.scene + "-" + what + ".png")).string(); };
  apps::write_png(path("reference"), apps::tone_mapped(a.reference, exposure), 1.0f);
  const Estimator side[] = {Estimator::uniform, Estimator::transmittance, Estimator::radiance};
  apps::Image strip(3 * a.width + 2 * 2, a.height);
  for (auto& px : strip.pixels()) px = glm::vec3(1.0f);  // white gaps
  int column = 0;
  for (const BudgetRow& r : a.rows) {
    if (r.budget != budget || !r.fits) continue;
    const apps::Image shown = apps::tone_mapped(r.image, exposure);
    apps::write_png(path(std::string(estimator_name(r.estimator))), shown, 1.0f);
    for (int i = 0; i < 3; ++i)
      if (side[i] == r.estimator) {
        for (int y = 0; y < a.height; ++y)
          for (int x = 0; x < a.width; ++x) strip.at(i * (a.width + 2) + x, y) = shown.at(x, y);
        ++column;
      }
  }
  if (column == 3) apps::write_png(path("equal-time"), strip, 1.0f);
  write_noise_maps(path("noise"), a);
  fmt::print("images    {}/media-{}-*.png (budget {}, the reference's exposure)\n", dir, a.scene, budget);
}

void print_scene(const SceneAccuracy& a, const AccuracyOptions& o) {
  fmt::print("\n== {}: {}x{}, {} photons emitted ({} stored), k = {}; unit = {:.4f} s simulated (transmittance, M = {} S)\n",
             a.scene, a.width, a.height, a.photons_emitted, a.photons_stored, a.k, a.unit_seconds, o.unit_b);
  fmt::print("reference: radiance, {:.3f} s simulated in two seeds (wall {:.1f} s); mean {:.4g}, own noise {:.3g} ({:.2f} %)\n",
             a.reference_seconds, a.reference_wall, a.reference_mean, a.reference_noise,
             a.reference_mean > 0 ? 100 * a.reference_noise / a.reference_mean : 0.0);
  fmt::print("{:<14} {:>6} {:>9} {:>9} {:>8} {:>10} {:>10} {:>9} {:>10}\n", "estimator", "budget", "b", "sim_s", "wall_s",
             "samples", "rmse", "rel_rmse", "/transm.");
  for (const BudgetRow& r : a.rows) {
    if (!r.fits) {
      fmt::print("{:<14} {:>6} {:>9}   (its fixed cost exceeds the budget)\n", estimator_name(r.estimator), r.budget, "-");
      continue;
    }
    const BudgetRow* t = a.row(Estimator::transmittance, r.budget);
    const std::string ratio = t && t->fits && t->rmse_net > 0 ? fmt::format("{:.3f}", r.rmse_net / t->rmse_net) : "-";
    fmt::print("{:<14} {:>6} {:>9.4g} {:>9.4f} {:>8.2f} {:>10} {:>10.4g} {:>8.2f}% {:>10}\n", estimator_name(r.estimator),
               r.budget, r.beta, r.simulated_seconds, r.wall_seconds, r.samples, r.rmse_net, 100 * r.relative_rmse, ratio);
  }
  fmt::print("rmse: against the reference, its own noise removed (sqrt(rmse^2 - noise^2)); b: M = b S (radiance: M = b c S_h, eq. 22)\n");
  fmt::print("noise spread (p95 / median of the per-pixel relative std over {} renders at budget {}):", o.spread_repeats,
             o.budgets.at(std::min(o.spread_budget, o.budgets.size() - 1)));
  for (const auto& [e, spread] : a.noise_spread) fmt::print(" {} {:.2f};", estimator_name(e), spread);
  fmt::print("\ngrid build: {:.4f} s simulated on one CPU, of the render at budget", a.grid_build_seconds);
  for (double b : o.budgets) fmt::print(" {}: {:.1f} %", b, 100 * a.grid_build_seconds / (b * a.unit_seconds));
  fmt::print(" (render cost grows with the pixels: at 640x480 divide by {:.0f})\n", 640.0 * 480 / (a.width * a.height));
  if (a.photon_rows.empty()) return;
  fmt::print("photon count at fixed samples (transmittance, M = {} S) against {} photons emitted:\n", a.photon_study_b,
             a.photon_reference_emitted);
  fmt::print("{:>10} {:>10} {:>10} {:>10} {:>8}\n", "emitted", "stored", "rmse", "mean bias", "wall_s");
  for (const PhotonRow& r : a.photon_rows)
    fmt::print("{:>10} {:>10} {:>10.4g} {:>9.2f}% {:>8.2f}\n", r.emitted, r.stored, r.rmse, 100 * r.mean_bias, r.wall_seconds);
}

std::string machine_name(const std::string& config) {
  return (config.empty() ? machine::default_machine_config() : machine::load_machine_config(config)).name;
}

// RMSE(a)/RMSE(b) per budget, both fitting.
std::vector<double> ratios(const SceneAccuracy& s, Estimator a, Estimator b, const std::vector<double>& budgets) {
  std::vector<double> out;
  for (double budget : budgets) {
    const BudgetRow *ra = s.row(a, budget), *rb = s.row(b, budget);
    if (ra && rb && ra->fits && rb->fits && rb->rmse_net > 0) out.push_back(ra->rmse_net / rb->rmse_net);
  }
  return out;
}

// goal: what a ratio at most `limit` means, e.g. "radiance sampling's error at most 0.6 x transmittance's".
void print_target(const std::string& what, const std::vector<double>& values, double limit, const std::string& goal) {
  if (values.empty()) return;
  const auto met = std::count_if(values.begin(), values.end(), [limit](double v) { return v <= limit; });
  std::string list;
  for (double v : values) list += fmt::format("{}{:.2f}", list.empty() ? "" : " ", v);
  fmt::print("  {:<58} {} (goal <= {}: {}): met at {} of {} budgets\n", what, list, limit, goal, met, values.size());
}

void print_targets(const std::vector<SceneAccuracy>& all, const AccuracyOptions& o) {
  fmt::print("\n== goals, as measured (ratios of RMSE at equal simulated time, one per budget)\n");
  for (const SceneAccuracy& s : all) {
    // Experiment 2 and its variants (exp2-bunny) ask 0.8; the fog, where transmittance sampling is
    // near ideal already, only that radiance sampling not lose more than 10 %; the rest 0.6.
    const bool fog = s.scene == "fog";
    const double limit = s.scene.rfind("exp2", 0) == 0 ? 0.8 : fog ? 1.1 : 0.6;
    print_target(s.scene + ": RMSE(radiance) / RMSE(transmittance)", ratios(s, Estimator::radiance, Estimator::transmittance, o.budgets),
                 limit,
                 fog ? "radiance sampling at most 10 % worse than transmittance sampling in uniform fog"
                     : fmt::format("radiance sampling cuts transmittance sampling's error by {:.0f} % or more", 100 * (1 - limit)));
    if (!fog)
      print_target(s.scene + ": RMSE(transmittance) / RMSE(uniform)",
                   ratios(s, Estimator::transmittance, Estimator::uniform, o.budgets), 1.0,
                   "transmittance sampling no worse than uniform marching");
    double spread_t = 0, spread_r = 0;
    for (const auto& [e, v] : s.noise_spread) {
      if (e == Estimator::transmittance) spread_t = v;
      if (e == Estimator::radiance) spread_r = v;
    }
    // The spread target is the paper's claim about its scenes; in the fog (and the small test scene)
    // transmittance sampling is already near ideal, so the ratio is shown without a target.
    const bool paper_scene = s.scene.rfind("exp", 0) == 0;
    if (spread_t > 0 && spread_r > 0)
      fmt::print("  {:<58} {:.3f} {}\n", s.scene + ": noise spread transmittance / radiance", spread_t / spread_r,
                 !paper_scene              ? "(no goal here: transmittance sampling is near ideal in this scene)"
                 : spread_t / spread_r >= 1.5 ? "(goal >= 1.5: radiance sampling's noise 1.5 x evener over the image): met"
                                              : "(goal >= 1.5: radiance sampling's noise 1.5 x evener over the image): not met");
    const double smallest = *std::min_element(o.budgets.begin(), o.budgets.end());
    const double share = s.grid_build_seconds / (smallest * s.unit_seconds);
    const double share_paper = share * s.width * s.height / (640.0 * 480.0);
    fmt::print("  {:<58} {:.1f} % here, {:.2f} % at 640x480 (the goal, at most 5 %, the paper's 7 s of grid against "
               "minutes of rendering, is on a whole run: gcsim run media)\n",
               s.scene + ": grid build / render at the smallest budget", 100 * share, 100 * share_paper);
  }
}

void write_csv(const std::string& path, const std::vector<SceneAccuracy>& all, const std::string& machine) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write CSV file '" + path + "'");
  // Every render runs on one CPU of the machine, timed by its counted operations: no network.
  f << pipeline::csv_comment("accuracy media", machine, "1 (one CPU)", "none (counted operations)") << '\n';
  f << "scene,estimator,budget,b,sim_s,wall_s,samples,rmse,rel_rmse\n";
  for (const SceneAccuracy& s : all)
    for (const BudgetRow& r : s.rows)
      if (r.fits)
        f << fmt::format("{},{},{},{:.6g},{:.6f},{:.3f},{},{:.6g},{:.6g}\n", s.scene, estimator_name(r.estimator), r.budget,
                         r.beta, r.simulated_seconds, r.wall_seconds, r.samples, r.rmse_net, r.relative_rmse);
}

nlohmann::json to_json(const SceneAccuracy& s) {
  nlohmann::json j{{"scene", s.scene},           {"width", s.width},
                   {"height", s.height},         {"photons_emitted", s.photons_emitted},
                   {"photons_stored", s.photons_stored}, {"unit_seconds", s.unit_seconds},
                   {"grid_build_seconds", s.grid_build_seconds}, {"reference_noise", s.reference_noise},
                   {"reference_mean", s.reference_mean}};
  for (const BudgetRow& r : s.rows)
    j["rows"].push_back({{"estimator", estimator_name(r.estimator)}, {"budget", r.budget}, {"fits", r.fits}, {"b", r.beta},
                         {"sim_s", r.simulated_seconds}, {"wall_s", r.wall_seconds}, {"samples", r.samples},
                         {"rmse", r.rmse_net}, {"rel_rmse", r.relative_rmse}});
  for (const auto& [e, v] : s.noise_spread) j["noise_spread"][std::string(estimator_name(e))] = v;
  for (const PhotonRow& r : s.photon_rows)
    j["photons"].push_back({{"emitted", r.emitted}, {"stored", r.stored}, {"rmse", r.rmse}, {"mean_bias", r.mean_bias}});
  return j;
}

// --csv and --json with the finished scenes; `extra` adds keys to the JSON (an interruption's).
void write_results(const AccuracyFlags& f, const std::vector<SceneAccuracy>& all, nlohmann::json j) {
  if (!f.csv.empty()) write_csv(f.csv, all, machine_name(f.config)), fmt::print("csv       {}\n", f.csv);
  if (!f.json.empty()) {
    j["scenes"] = nlohmann::json::array();
    for (const SceneAccuracy& s : all) j["scenes"].push_back(to_json(s));
    pipeline::write_json_file(f.json, j);
  }
}

void run_accuracy(AccuracyFlags f) {
  if (f.quick) {
    f.o.width = 64, f.o.height = 48, f.o.photons = f.o.photons > 0 ? f.o.photons : 20000;
    f.budgets = {"2", "8"}, f.photon_fractions = {"0.5", "1"}, f.o.reference_factor = 8, f.o.spread_repeats = 8;
    f.o.spread_budget = 0;
  }
  pipeline::check_writable(f.csv, "--csv");  // before the renders
  pipeline::check_writable(f.json, "--json");
  const machine::MachineConfig m = f.config.empty() ? machine::default_machine_config() : machine::load_machine_config(f.config);
  f.o.budgets = pipeline::parse_double_list(f.budgets, "--budgets");
  f.o.photon_fractions = pipeline::list_is_empty(f.photon_fractions)
                             ? std::vector<double>{}
                             : pipeline::parse_double_list(f.photon_fractions, "--photon-fractions");
  f.o.estimators.clear();
  for (const auto& name : split_names(f.estimators)) {
    const auto e = parse_estimator(name);
    if (!e || *e == Estimator::grid)
      throw std::invalid_argument("--estimators: '" + name + "': expected uniform, transmittance, radiance, equiangular or mis");
    f.o.estimators.push_back(*e);
  }
  std::vector<SceneAccuracy> all;
  const std::vector<std::string> names = split_names(f.scenes);
  pipeline::ProgressLine progress("accuracy media", 0);  // a fraction: shown for one scene too
  std::string at;  // what is being measured: an interrupted run says so
  try {
    for (const auto& name : names) {
      const MediaScene scene = load_media_scene(name);
      // measure_accuracy renders without the simulated machine: its progress calls are where an
      // interruption (SIGINT/SIGTERM) is noticed, one render apart.
      all.push_back(measure_accuracy(scene, f.o, m, [&](const std::string& what) {
        at = name + ": " + what;
        parix::host::throw_if_interrupted();
        progress.update_fraction(double(all.size()) / double(names.size()), at);
      }));
      progress.clear();
      print_scene(all.back(), f.o);
      if (!f.images.empty())
        write_images(f.images, all.back(), f.o.budgets.at(std::min(f.o.spread_budget, f.o.budgets.size() - 1)));
      std::fflush(stdout);
    }
  } catch (const parix::host::Interrupted&) {
    progress.clear();
    fmt::print("\ninterrupted at {}; {} of {} scenes finished\n", at, all.size(), names.size());
    write_results(f, all, nlohmann::json{{"interrupted", true}, {"interrupted_at", at}});
    throw;
  }
  print_targets(all, f.o);
  write_results(f, all, nlohmann::json::object());
}

}  // namespace

void add_accuracy_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<AccuracyFlags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "media",
      "What accuracy costs in the media renderer: each scene rendered with each estimator at equal budgets\n"
      "of simulated time (one CPU of the machine, from counted operations: deterministic), RMSE against a\n"
      "high-sample reference (radiance sampling, two seeds) on the same photon map (so only the estimators differ), the noise spread\n"
      "over the image, the SH grid's share of the render time, the photon count's effect at fixed samples,\n"
      "and each goal (e.g. radiance sampling's error at most 0.6 x transmittance's) as measured. Wall times are the host's.");
  pipeline::add_list_option(cmd, "--scenes", f->scenes, "Scenes: built-in names (exp1, exp2, fog, small, exp1-literal, exp1-bunny, exp2-bunny) or scene files with a medium")->capture_default_str();
  pipeline::add_list_option(cmd, "--estimators", f->estimators, "Estimators to compare")->capture_default_str();
  pipeline::add_list_option(cmd, "--budgets", f->budgets, "Budgets in units (the transmittance estimator's time at M = unit-b S)")
      ->capture_default_str();
  cmd->add_option("--unit-b", f->o.unit_b, "b of the budget unit")->check(pipeline::positive_number())->capture_default_str();
  cmd->add_option("--width", f->o.width, "Image width")->check(CLI::Range(4, 4096))->capture_default_str();
  cmd->add_option("--height", f->o.height, "Image height")->check(CLI::Range(4, 4096))->capture_default_str();
  cmd->add_option("--photons", f->o.photons, "Photons emitted (default: the scene's)")->check(pipeline::positive_number());
  cmd->add_option("--reference-factor", f->o.reference_factor, "Reference budget over the largest budget")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--alpha", f->o.density.defensive_alpha,
                  "Transmittance share of the defensive radiance density (radiance and MIS estimators, and the reference)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-voxel-optical-depth", f->o.density.max_voxel_optical_depth,
                  "Radiance sampling draws from the transmittance where voxels are thicker than this many mean free paths "
                  "(1e9: the paper's density everywhere)")
      ->check(pipeline::positive_number())
      ->capture_default_str();
  cmd->add_option("--repeats", f->o.spread_repeats, "Renders per estimator for the noise spread")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  pipeline::add_list_option(cmd, "--photon-fractions", f->photon_fractions, "Photon study: fractions of the scene's photons (empty: skip)")
      ->capture_default_str();
  cmd->add_option("--seed", f->o.seed, "Random seed")->capture_default_str();
  cmd->add_flag("--quick", f->quick, "CI-sized: 64x48, 20000 photons, budgets 2,8, reference x8, 8 repeats");
  pipeline::add_config_option(cmd, f->config, "Machine file whose [ops] costs turn counts into seconds");
  cmd->add_option("--csv", f->csv, "Write scene,estimator,budget,b,sim_s,wall_s,samples,rmse,rel_rmse (gcsim plot --accuracy)");
  pipeline::add_json_option(cmd, f->json, "every table");
  cmd->add_option("--images", f->images, "Write each estimator's image at the noise-spread budget, and the reference, as PNGs here");
  cmd->footer(
      "\nExamples:\n"
      "  gcsim accuracy media --quick\n"
      "  gcsim accuracy media --csv media.csv && gcsim plot --accuracy media.csv --out plots/");
  cmd->callback([f] { run_accuracy(*f); });
}

}  // namespace gcsim::media::app
