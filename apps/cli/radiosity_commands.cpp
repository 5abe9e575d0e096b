// gcsim run/sweep/accuracy radiosity and gcsim scene info: the thesis's chapters 3 and 4 from the
// command line.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <type_traits>

#include <fmt/format.h>

#include "apps/cli/commands.hpp"
#include "apps/cli/run_support.hpp"
#include "apps/common/image.hpp"
#include "apps/radiosity/accuracy.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/gauss_seidel.hpp"
#include "apps/radiosity/gouraud_renderer.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/thesis_tables.hpp"
#include "apps/common/scene/world_loader.hpp"

namespace gcsim::cli {

namespace rad = gcsim::radiosity;

namespace {

struct SolveFlags {
  std::string scene = "cornell";
  int hemicube = 256;
  int shooters = 2;
  double energy = 0.999;
  std::string parallel = "hemicube-fixed";
  std::string bcast = "sequential";
  bool aggregate = false;
  bool keep_links = false;
  int levels = 3;
  int cells = 8;
  int max_steps = 1000000;
  std::string order = "energy";
  double sort_until = 0.9;
};

void add_solve_options(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("--scene", f.scene, "room, picroom, cornell (thesis table 4.1) or the path of a WORLD file")
      ->capture_default_str();
  cmd->add_option("--hemicube", f.hemicube,
                  "Hemicube resolution: pixels across the top face (side faces are half as high). Cost and "
                  "accuracy of the form factors grow with it")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--shooters", f.shooters, "K: patches that shoot per loop, those with the most unshot energy (thesis: 2)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--energy", f.energy, "Stop once this fraction of the energy has been shot (thesis: 0.999)")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            double x = -1;
            try {
              std::size_t used = 0;
              x = std::stod(v, &used);
              if (used != v.size()) return "'" + v + "' is not a number";
            } catch (const std::exception&) {
              return "'" + v + "' is not a number";
            }
            return x >= 0 && x < 1 ? "" : "must be in [0, 1): reflected light keeps some energy unshot forever";
          },
          "in [0, 1)"))
      ->capture_default_str();
  cmd->add_option("--parallel", f.parallel,
                  "hemicube-fixed (4.3: hemicube cells spread over the nodes), hemicube-hierarchical (4.5: "
                  "border cells split into four, recursively), patch (4.2.2: each shooter's owner computes "
                  "its whole hemicube)")
      ->check(CLI::IsMember({"hemicube-fixed", "hemicube-hierarchical", "patch"}))
      ->capture_default_str();
  cmd->add_option("--bcast", f.bcast,
                  "All-node broadcast: sequential (everyone to the root in turn and back, table 4.6) or tree "
                  "(leaves to root and back, table 4.7)")
      ->check(CLI::IsMember({"sequential", "tree"}))
      ->capture_default_str();
  cmd->add_flag("--aggregate", f.aggregate,
                "4.4.3: one larger exchange per loop (the replicas choose the shooters themselves and every "
                "shooter's form factors travel together) instead of K + 1 exchanges");
  cmd->add_flag("--keep-links", f.keep_links,
                "Open each link once and reuse it (the thesis opened a connection for every message)");
  cmd->add_option("--levels", f.levels, "hemicube-hierarchical: levels of subdivision below the coarse cells")
      ->check(CLI::Range(1, 6))
      ->capture_default_str();
  cmd->add_option("--cells", f.cells,
                  "Hemicube partition: T x T cells on the top face, T x T/2 per side face (even)")
      ->check(CLI::Range(2, 512))
      ->capture_default_str();
  cmd->add_option("--order", f.order,
                  "How shooters are chosen: energy (the K largest unshot energies, 3.5.2), index (patch order "
                  "without sorting, 4.4.1: saves the proposal exchange but converges more slowly), "
                  "energy-then-index (sort until --sort-until, then index order, 4.4.1)")
      ->check(CLI::IsMember({"energy", "index", "energy-then-index"}))
      ->capture_default_str();
  cmd->add_option("--sort-until", f.sort_until, "energy-then-index: shot fraction at which sorting stops")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-steps", f.max_steps, "Give up after this many loops")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str();
}

rad::ParallelOptions parallel_options(const SolveFlags& f) {
  rad::ParallelOptions o;
  o.solver.hemicube.resolution = f.hemicube;
  o.solver.hemicube.cells_per_side = f.cells;
  o.solver.shooters = f.shooters;
  o.solver.energy = f.energy;
  o.solver.max_steps = f.max_steps;
  o.solver.order = rad::parse_shooting_order(f.order);
  o.solver.sort_until = f.sort_until;
  o.algorithm = rad::parse_parallel_algorithm(f.parallel);
  o.bcast = f.bcast == "tree" ? parix::BcastAlgo::tree : parix::BcastAlgo::sequential;
  o.aggregate = f.aggregate;
  o.keep_links = f.keep_links;
  o.hierarchical_levels = f.levels;
  // Fail early, with the reason, on an impossible hemicube / partition combination.
  rad::HemicubeOptions check = o.solver.hemicube;
  if (o.algorithm == rad::ParallelAlgorithm::hemicube_hierarchical) check.hierarchical_levels = f.levels;
  rad::Scene empty;
  rad::HemicubeRenderer probe(empty, check);
  return o;
}

// Comma-separated values. Each item must convert in full (and, for integers, be positive);
// otherwise the error names the option, the item and `expected`, what each item should be.
template <class T>
std::vector<T> parse_list(const std::string& s, const char* what, const char* expected, bool allow_empty = false) {
  std::vector<T> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      T x;
      if constexpr (std::is_integral_v<T>) x = std::stoi(item, &used);
      else x = std::stod(item, &used);
      if (used != item.size() || (std::is_integral_v<T> && x < 1)) throw std::invalid_argument(item);
      v.push_back(x);
    } catch (const std::exception&) {
      throw std::invalid_argument(fmt::format("{}: '{}' is not {}", what, item, expected));
    }
  }
  if (v.empty() && !allow_empty) throw std::invalid_argument(fmt::format("{}: empty list", what));
  return v;
}

std::vector<int> parse_int_list(const std::string& s, const char* what) {
  return parse_list<int>(s, what, "a positive integer (expected e.g. 1,2,4,8)");
}

std::vector<double> parse_double_list(const std::string& s, const char* what) {
  return parse_list<double>(s, what, "a number");
}

// "ex,ey,ez,tx,ty,tz[,fov]"
rad::Camera parse_camera(const std::string& s) {
  const std::vector<double> v = parse_list<double>(s, "--camera", "a number (expected ex,ey,ez,tx,ty,tz[,fov])", true);
  if (v.size() != 6 && v.size() != 7)
    throw std::invalid_argument(fmt::format("--camera: expected 6 or 7 numbers (ex,ey,ez,tx,ty,tz[,fov]), got {}", v.size()));
  rad::Camera c;
  c.eye = {v[0], v[1], v[2]};
  c.target = {v[3], v[4], v[5]};
  if (v.size() == 7) c.fov_y_degrees = v[6];
  if (!(c.fov_y_degrees > 0.01 && c.fov_y_degrees < 179)) throw std::invalid_argument("--camera: field of view must be in (0.01, 179) degrees");
  if (glm::length(c.target - c.eye) == 0) throw std::invalid_argument("--camera: eye and target coincide");
  return c;
}

struct RunOutcome {
  parix::RunResult run;
  rad::ParallelOutcome result;
};

RunOutcome simulate(const rad::Scene& scene, const rad::ParallelOptions& o, const parix::SimulationOptions& sim) {
  RunOutcome out;
  out.run = parix::run_simulated(sim, [&](parix::Processor& p) { rad::radiosity_program(p, scene, o, &out.result); });
  return out;
}

void print_loops_table(const rad::ParallelOutcome& r, const std::string& scene_name, int shooters) {
  const rad::thesis::SceneFigures* fig = rad::thesis::figures_for(scene_name);
  fmt::print("\nloops to shoot a fraction of the energy (thesis table 4.2{})\n",
             shooters == 2 ? "" : "; the thesis used 2 shooters per loop");
  fmt::print("  {:>7}  {:>7}  {:>7}\n", "energy%", "loops", "thesis");
  for (std::size_t i = 0; i < rad::thesis::kEnergyPercent.size(); ++i) {
    double frac = rad::thesis::kEnergyPercent[i] / 100;
    int loops = -1;
    for (const auto& s : r.steps)
      if (s.shot_fraction >= frac) {
        loops = s.step;
        break;
      }
    std::string ours = loops < 0 ? "-" : fmt::format("{}", loops);
    std::string theirs = fig && fig->loops_for_energy[i] >= 0 ? fmt::format("{}", fig->loops_for_energy[i]) : "-";
    fmt::print("  {:>7}  {:>7}  {:>7}\n", rad::thesis::kEnergyPercent[i], ours, theirs);
  }
}

void write_steps_csv(const std::string& path, const rad::ParallelOutcome& r) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write CSV file '" + path + "'");
  out << "step,shot_fraction,shooters\n";
  for (const auto& s : r.steps) {
    out << s.step << ',' << fmt::format("{:.9f}", s.shot_fraction) << ',';
    for (std::size_t k = 0; k < s.shooters.size(); ++k) out << (k ? " " : "") << s.shooters[k];
    out << '\n';
  }
}

void add_run(CommandGroups& g) {
  struct Flags {
    MachineOptions machine;
    SolveFlags solve;
    std::string image, camera, steps_csv, snapshots;
    int width = 0, height = 0;
    double exposure = 0;
    bool gauss_seidel = false;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.run->add_subcommand(
      "radiosity",
      "Progressive-refinement radiosity (thesis ch. 3-4) on the simulated GC.\n\n"
      "Each loop the K patches with the most unshot energy (delta B * A) shoot: a hemicube on each\n"
      "patch gives the form factors to every element by Z-buffering (eqs. 3.19-3.21), and every element\n"
      "receives rho * delta B * F * A_patch / A_element. Patches shoot, elements receive. The run stops\n"
      "when the shot fraction of the emitted energy reaches --energy.\n\n"
      "On N nodes every node keeps a replica of the scene; --parallel picks how the work is split and\n"
      "--bcast/--aggregate how the results are exchanged. Every variant gives the same radiosities as\n"
      "one node. The run prints simulated seconds (what the GC would take) next to wall seconds.");
  add_machine_options(cmd, f->machine);
  add_solve_options(cmd, f->solve);
  cmd->add_option("--image", f->image, "Write a PNG: Z-buffer, radiosities interpolated at vertices (Gouraud)");
  cmd->add_option("--camera", f->camera, "Camera as ex,ey,ez,tx,ty,tz[,fov_y_degrees]; default: the scene's own");
  cmd->add_option("--width", f->width, "Image width (default 512)")->check(CLI::Range(8, 8192));
  cmd->add_option("--height", f->height, "Image height (default 512, 384 for the rooms)")->check(CLI::Range(8, 8192));
  cmd->add_option("--exposure", f->exposure, "Multiply radiosities by this before display; default: automatic");
  cmd->add_option("--steps-csv", f->steps_csv, "Write the shot fraction after every loop as CSV (table 4.2 analog)");
  cmd->add_option("--snapshots", f->snapshots,
                  "With --image: also write the image after these loops (e.g. 1,10,50), as IMAGE_loopN.png: "
                  "the progression of figures 4.10-4.12");
  cmd->add_flag("--gauss-seidel", f->gauss_seidel,
                "Also solve with full-matrix Gauss-Seidel (3.5.1) on the host and print how far the progressive "
                "result is from it (small scenes only)");
  cmd->footer(
      "\nExamples:\n"
      "  gcsim run radiosity --scene cornell --nodes 8 --json r.json --image c.png\n"
      "  gcsim run radiosity --scene room --nodes 16 --bcast tree --steps-csv loops.csv\n"
      "  gcsim run radiosity --scene picroom --parallel hemicube-hierarchical --levels 2 --nodes 8\n"
      "  gcsim run radiosity --scene cornell --nodes 8 --order index --max-steps 2000   (thesis 4.4.1)\n"
      "  gcsim run radiosity --scene tests/radiosity/fixtures/opposing_squares_lit.wld --energy 0.99999");
  cmd->callback([f] {
    rad::World world = rad::load_scene_world(f->solve.scene);
    rad::Scene scene = rad::flatten(world);
    rad::ParallelOptions o = parallel_options(f->solve);
    parix::SimulationOptions sim = simulation_options(f->machine, 1);
    // Checked before the run, so that a typo does not cost a whole simulation.
    std::optional<rad::Camera> camera;
    if (!f->camera.empty()) camera = parse_camera(f->camera);
    if (!f->snapshots.empty()) {
      if (f->image.empty()) throw std::invalid_argument("--snapshots needs --image (the snapshots are named after it)");
      o.snapshot_loops = parse_int_list(f->snapshots, "--snapshots");
    }
    auto c = scene.counts();
    fmt::print("scene     {}: {} instances, {} surfaces, {} patches, {} elements, {} vertices\n", scene.name,
               c.instances, c.surfaces, c.patches, c.elements, c.vertices);
    fmt::print("solver    {} on {} nodes, bcast {}{}{}{}, hemicube {}, {} shooters per loop, energy {}\n",
               rad::to_string(o.algorithm), sim.nodes, f->solve.bcast, o.aggregate ? ", aggregated" : "",
               o.keep_links ? ", links kept" : "",
               o.solver.order == rad::ShootingOrder::energy ? "" : fmt::format(", order {}", rad::to_string(o.solver.order)),
               o.solver.hemicube.resolution, o.solver.shooters, o.solver.energy);
    RunOutcome out = simulate(scene, o, sim);
    const auto& r = out.result;
    fmt::print("loops     {} (shot fraction {:.6f}{})\n", r.steps.size(),
               r.steps.empty() ? 1.0 : r.steps.back().shot_fraction, r.converged ? "" : ", threshold NOT reached");
    rad::Rgb bal = r.energy.emitted - r.energy.unshot - r.energy.absorbed - r.energy.escaped;
    fmt::print("energy    emitted {:.6g}, absorbed {:.6g}, unshot {:.6g}, escaped {:.6g}, imbalance {:.3g}\n",
               rad::channel_sum(r.energy.emitted), rad::channel_sum(r.energy.absorbed),
               rad::channel_sum(r.energy.unshot), rad::channel_sum(r.energy.escaped), rad::channel_sum(bal));
    nlohmann::json extra;
    extra["radiosity"] = {{"scene", scene.name},
                          {"counts", {{"instances", c.instances}, {"surfaces", c.surfaces}, {"patches", c.patches},
                                      {"elements", c.elements}, {"vertices", c.vertices}}},
                          {"parallel", rad::to_string(o.algorithm)},
                          {"bcast", f->solve.bcast},
                          {"aggregate", o.aggregate},
                          {"keep_links", o.keep_links},
                          {"order", rad::to_string(o.solver.order)},
                          {"hemicube", o.solver.hemicube.resolution},
                          {"shooters", o.solver.shooters},
                          {"energy_threshold", o.solver.energy},
                          {"loops", r.steps.size()},
                          {"shot_fraction", r.steps.empty() ? 1.0 : r.steps.back().shot_fraction},
                          {"converged", r.converged}};
    if (f->gauss_seidel) {
      auto gs = rad::solve_gauss_seidel(scene, o.solver.hemicube);
      double worst = 0, mean = 0, area = 0;
      for (std::size_t e = 0; e < scene.elements.size(); ++e) {
        mean += rad::channel_sum(gs.element_radiosity[e]) / 3 * scene.elements[e].area;
        area += scene.elements[e].area;
      }
      mean /= area;
      for (std::size_t e = 0; e < scene.elements.size(); ++e) {
        rad::Rgb d = glm::abs(r.element_radiosity[e] - gs.element_radiosity[e]);
        worst = std::max({worst, d.r, d.g, d.b});
      }
      fmt::print("gauss-seidel {} sweeps; largest element difference from progressive: {:.3g} ({:.3g}% of the mean)\n",
                 gs.iterations, worst, mean > 0 ? 100 * worst / mean : 0.0);
      extra["radiosity"]["gauss_seidel_max_difference"] = worst;
    }
    print_loops_table(r, scene.name, o.solver.shooters);
    fmt::print("\n");
    if (!f->steps_csv.empty()) {
      write_steps_csv(f->steps_csv, r);
      fmt::print("csv       {}\n", f->steps_csv);
    }
    if (!f->image.empty()) {
      rad::Camera cam = camera ? *camera : (scene.camera ? *scene.camera : rad::default_camera(scene));
      rad::RenderOptions ro;
      bool room = scene.name == "ROOM" || scene.name == "PICROOM";
      ro.width = f->width > 0 ? f->width : 512;
      ro.height = f->height > 0 ? f->height : (room ? 384 : 512);
      ro.exposure = f->exposure;
      apps::Image final_image = rad::render_gouraud(scene, r.element_radiosity, cam, ro);
      apps::write_png(f->image, final_image);
      fmt::print("image     {}\n", f->image);
      if (!r.snapshots.empty()) {
        // Same exposure as the final image, so that the images show light arriving.
        if (ro.exposure <= 0) ro.exposure = rad::auto_exposure(scene, r.element_radiosity, cam, ro);
        std::filesystem::path base(f->image);
        for (const auto& [loop, b] : r.snapshots) {
          std::filesystem::path p = base.parent_path() / fmt::format("{}_loop{}{}", base.stem().string(), loop,
                                                                      base.extension().string());
          apps::write_png(p, rad::render_gouraud(scene, b, cam, ro));
          fmt::print("snapshot  {} (after loop {})\n", p.string(), loop);
        }
      }
      extra["radiosity"]["image"] = f->image;
    }
    report_run(out.run, f->machine, extra);
  });
}

void add_sweep(CommandGroups& g) {
  struct Flags {
    SolveFlags solve;
    MachineOptions machine;  // --config and --model
    std::string nodes = "1,2,4,8,16,32,64", csv, json;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.sweep->add_subcommand(
      "radiosity",
      "Run radiosity for several node counts and print, per count, simulated seconds, speedup over the\n"
      "first count, simulated communication seconds (mean per node) and wall seconds, next to the\n"
      "thesis's tables 4.3/4.4/4.5 (sequential broadcast) or 4.8 (tree broadcast) for built-in scenes.\n"
      "The thesis's shape: time falls with more nodes at first, then rises as communication dominates.");
  add_solve_options(cmd, f->solve);
  add_machine_choice_options(cmd, f->machine);
  cmd->add_option("--nodes", f->nodes, "Comma-separated node counts")->capture_default_str();
  cmd->add_option("--csv", f->csv, "Write the table as CSV");
  cmd->add_option("--json", f->json, "Write every run's JSON summary as one array");
  cmd->footer(
      "\nExamples:\n"
      "  gcsim sweep radiosity --scene cornell\n"
      "  gcsim sweep radiosity --scene cornell --bcast tree --csv tree.csv\n"
      "  gcsim sweep radiosity --scene room --aggregate --nodes 1,8,64");
  cmd->callback([f] {
    std::vector<int> counts = parse_int_list(f->nodes, "--nodes");
    rad::World world = rad::load_scene_world(f->solve.scene);
    rad::Scene scene = rad::flatten(world);
    rad::ParallelOptions o = parallel_options(f->solve);
    const bool tree = o.bcast == parix::BcastAlgo::tree;
    const rad::thesis::SceneFigures* fig = rad::thesis::figures_for(scene.name);
    fmt::print("{}: {} / bcast {}{}{} / hemicube {} / K {} / energy {}\n", scene.name, rad::to_string(o.algorithm),
               f->solve.bcast, o.aggregate ? " aggregated" : "", o.keep_links ? " links kept" : "",
               o.solver.hemicube.resolution, o.solver.shooters,
               o.solver.energy);
    fmt::print("{:>5} {:>10} {:>8} {:>10} {:>9} {:>6} | {:>9} {:>8} {:>9}\n", "nodes", "sim_s", "speedup", "comm_s",
               "wall_s", "loops", "thesis_s", "thesis_x", "thesis_c");
    std::ofstream csv;
    if (!f->csv.empty()) {
      csv.open(f->csv);
      if (!csv) throw std::runtime_error("cannot write CSV file '" + f->csv + "'");
      csv << "nodes,simulated_s,speedup,comm_s,wall_s,loops,thesis_s,thesis_speedup,thesis_comm_s\n";
    }
    nlohmann::json all = nlohmann::json::array();
    double first = 0, best_time = 0;
    int best_nodes = 0;
    std::vector<rad::Rgb> reference;
    for (int n : counts) {
      MachineOptions mo = f->machine;
      mo.nodes = n;
      parix::SimulationOptions sim = simulation_options(mo, n);
      RunOutcome out = simulate(scene, o, sim);
      double t = out.run.simulated_seconds();
      if (first == 0) first = t;
      if (best_nodes == 0 || t < best_time) best_nodes = n, best_time = t;
      if (reference.empty()) reference = out.result.element_radiosity;
      else if (reference != out.result.element_radiosity)
        fmt::print("warning: radiosities on {} nodes differ from the first run\n", n);
      int ti = rad::thesis::node_index(n);
      double th_t = -1, th_x = -1, th_c = -1;
      if (fig && ti >= 0) {
        th_t = tree ? fig->time_tree_bcast[ti] : fig->time_sequential_bcast[ti];
        th_x = 100.0 * (tree ? fig->time_tree_bcast[0] : fig->time_sequential_bcast[0]) / th_t / 100.0;
        th_c = tree ? -1 : fig->comm_seconds[ti];
      }
      auto cell = [](double v, const char* fmtspec) { return v < 0 ? std::string("-") : fmt::format(fmt::runtime(fmtspec), v); };
      fmt::print("{:>5} {:>10.2f} {:>8.2f} {:>10.2f} {:>9.2f} {:>6} | {:>9} {:>8} {:>9}\n", n, t, first / t,
                 out.run.mean_comm_seconds(), out.run.wall_seconds, out.result.steps.size(), cell(th_t, "{:.0f}"),
                 cell(th_x, "{:.2f}"), cell(th_c, "{:.0f}"));
      std::fflush(stdout);
      if (csv)
        csv << fmt::format("{},{:.6f},{:.6f},{:.6f},{:.6f},{},{},{},{}\n", n, t, first / t, out.run.mean_comm_seconds(),
                           out.run.wall_seconds, out.result.steps.size(), th_t < 0 ? "" : fmt::format("{}", th_t),
                           th_x < 0 ? "" : fmt::format("{:.4f}", th_x), th_c < 0 ? "" : fmt::format("{}", th_c));
      nlohmann::json j = out.run.to_json();
      j["radiosity"] = {{"scene", scene.name}, {"loops", out.result.steps.size()}, {"nodes", n}};
      all.push_back(j);
    }
    if (best_nodes > 0) {
      std::string theirs;
      if (fig) {
        const auto& t = tree ? fig->time_tree_bcast : fig->time_sequential_bcast;
        int bi = int(std::min_element(t.begin(), t.end()) - t.begin());
        theirs = fmt::format(" (thesis: {} nodes)", rad::thesis::kNodes[bi]);
      }
      fmt::print("fastest on {} nodes{}\n", best_nodes, theirs);
    }
    if (fig) fmt::print("thesis_x: speedup over 1 node from the thesis's table {}; thesis_c: table 4.5\n", tree ? "4.8" : "4.3");
    if (!f->csv.empty()) fmt::print("csv  {}\n", f->csv);
    if (!f->json.empty()) {
      write_json_file(f->json, all);
      fmt::print("json {}\n", f->json);
    }
  });
}

void add_accuracy(CommandGroups& g) {
  struct Flags {
    std::string resolutions = "16,32,64,128,256,512";
    std::string thresholds = "0.9,0.95,0.99,0.995,0.999,0.9999";
    std::string levels = "1,2,3,4";
    int hierarchical_hemicube = 256;
    std::string scene = "cornell", config;
    int hemicube = 64;
    int shooters = 2;
    std::string json;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "radiosity",
      "What accuracy costs in radiosity, as three tables.\n"
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
      "Times are simulated seconds on one node of the machine (counted operations) and host wall seconds.");
  cmd->add_option("--resolutions", f->resolutions, "Hemicube resolutions for table 1")->capture_default_str();
  cmd->add_option("--thresholds", f->thresholds, "Energy thresholds for table 2, ascending")->capture_default_str();
  cmd->add_option("--scene", f->scene, "Scene for tables 2 and 3")->capture_default_str();
  cmd->add_option("--levels", f->levels, "Hierarchical levels for table 3 (empty: skip the table)")->capture_default_str();
  cmd->add_option("--hierarchical-hemicube", f->hierarchical_hemicube, "Hemicube resolution for table 3")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--hemicube", f->hemicube, "Hemicube resolution for table 2")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--shooters", f->shooters, "Shooters per loop for table 2")->check(CLI::Range(1, 1 << 20))->capture_default_str();
  cmd->add_option("--config", f->config, "Machine file whose [ops] costs turn counts into seconds")->check(CLI::ExistingFile);
  cmd->add_option("--json", f->json, "Write both tables as JSON");
  cmd->callback([f] {
    machine::MachineConfig m = f->config.empty() ? machine::default_machine_config() : machine::load_machine_config(f->config);
    std::vector<int> res = parse_int_list(f->resolutions, "--resolutions");
    for (int r : res)
      if (r % 2 != 0 || r < 8) throw std::invalid_argument(fmt::format("--resolutions: {} must be even and at least 8", r));
    std::vector<double> th = parse_double_list(f->thresholds, "--thresholds");
    for (std::size_t i = 0; i < th.size(); ++i)
      if (th[i] <= 0 || th[i] >= 1 || (i > 0 && th[i] <= th[i - 1]))
        throw std::invalid_argument("--thresholds: expected ascending fractions in (0, 1)");
    nlohmann::json j;
    fmt::print("1. hemicube form factors against closed forms (relative errors)\n");
    fmt::print("{:<46} {:>5} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10} {:>8}\n", "case", "res", "point", "exact",
               "error", "area", "exact", "error", "sim_s", "wall_s");
    auto ff = rad::form_factor_accuracy(res, m);
    for (const auto& a : ff) {
      fmt::print("{:<46} {:>5} {:>9.6f} {:>9.6f} {:>9.2e} {:>9.6f} {:>9.6f} {:>9.2e} {:>10.4f} {:>8.3f}\n",
                 rad::to_string(a.form_factor_case), a.resolution, a.hemicube_point, a.exact_point, a.point_error(),
                 a.hemicube_area, a.exact_area, a.area_error(), a.simulated_seconds, a.wall_seconds);
      j["form_factors"].push_back({{"case", rad::to_string(a.form_factor_case)}, {"resolution", a.resolution},
                                   {"point", a.hemicube_point}, {"exact_point", a.exact_point},
                                   {"point_error", a.point_error()}, {"area", a.hemicube_area},
                                   {"exact_area", a.exact_area}, {"area_error", a.area_error()},
                                   {"simulated_s", a.simulated_seconds}, {"wall_s", a.wall_seconds}});
    }
    rad::Scene scene = rad::flatten(rad::load_scene_world(f->scene));
    rad::SolverOptions so;
    so.hemicube.resolution = f->hemicube;
    so.shooters = f->shooters;
    fmt::print("\n2. {} radiosities against converged Gauss-Seidel (hemicube {}, K {}); errors relative to the mean radiosity\n",
               scene.name, f->hemicube, f->shooters);
    fmt::print("{:>9} {:>6} {:>10} {:>10} {:>10} {:>8}\n", "energy", "loops", "rms_err", "max_err", "sim_s", "wall_s");
    auto ea = rad::energy_accuracy(scene, so, th, m);
    for (const auto& a : ea) {
      fmt::print("{:>9} {:>6} {:>10.3e} {:>10.3e} {:>10.3f} {:>8.3f}\n", a.threshold, a.steps, a.rms_relative_error,
                 a.max_relative_error, a.simulated_seconds, a.wall_seconds);
      j["energy"].push_back({{"threshold", a.threshold}, {"loops", a.steps}, {"rms_error", a.rms_relative_error},
                             {"max_error", a.max_relative_error}, {"simulated_s", a.simulated_seconds},
                             {"wall_s", a.wall_seconds}});
    }
    if (ea.size() < th.size()) fmt::print("(thresholds above {} were not reached)\n", ea.empty() ? 0.0 : ea.back().threshold);
    if (!f->levels.empty()) {
      std::vector<int> lv = parse_int_list(f->levels, "--levels");
      for (int l : lv)
        if (f->hierarchical_hemicube % (2 << l) != 0 || f->hierarchical_hemicube / (1 << l) < 8)
          throw std::invalid_argument(fmt::format(
              "--levels: {} levels need a hemicube resolution that is a multiple of {} and at least {}", l, 2 << l,
              8 << l));
      rad::SolverOptions ho = so;
      ho.hemicube.resolution = f->hierarchical_hemicube;
      fmt::print("\n3. {} hierarchical hemicube against the fixed hemicube {} (energy {}, K {}); errors relative to the mean\n",
                 scene.name, f->hierarchical_hemicube, ho.energy, ho.shooters);
      fmt::print("{:>7} {:>6} {:>10} {:>10} {:>10} {:>8}\n", "levels", "loops", "rms_err", "max_err", "sim_s", "wall_s");
      for (const auto& a : rad::hierarchical_accuracy(scene, ho, lv, m)) {
        fmt::print("{:>7} {:>6} {:>10.3e} {:>10.3e} {:>10.3f} {:>8.3f}\n", a.levels == 0 ? std::string("fixed") : fmt::format("{}", a.levels),
                   a.steps, a.rms_relative_error, a.max_relative_error, a.simulated_seconds, a.wall_seconds);
        j["hierarchical"].push_back({{"levels", a.levels}, {"loops", a.steps}, {"rms_error", a.rms_relative_error},
                                     {"max_error", a.max_relative_error}, {"simulated_s", a.simulated_seconds},
                                     {"wall_s", a.wall_seconds}});
      }
    }
    if (!f->json.empty()) write_json_file(f->json, j);
  });
}

void add_table(CommandGroups& g) {
  struct Flags {
    int hemicube = 256;
    int shooters = 2;
    std::string csv;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.table->add_subcommand(
      "radiosity",
      "The thesis's tables 4.1 (scene counts) and 4.2 (progressive-refinement loops needed to shoot a\n"
      "given fraction of the energy) for ROOM, PICROOM and CORNELL, next to the published figures.\n"
      "Loop counts come from the sequential solver (they do not depend on the node count).");
  cmd->add_option("--hemicube", f->hemicube, "Hemicube resolution")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--shooters", f->shooters, "Shooters per loop (the thesis: 2)")->check(CLI::Range(1, 1 << 20))->capture_default_str();
  cmd->add_option("--csv", f->csv, "Write table 4.2 as CSV");
  cmd->callback([f] {
    fmt::print("table 4.1: scenes ({} / thesis)\n", "this");
    fmt::print("{:<8} {:>11} {:>11} {:>11} {:>11} {:>11}\n", "scene", "instances", "surfaces", "patches", "elements", "vertices");
    std::vector<rad::Scene> scenes;
    for (const auto& name : rad::builtin_scene_names()) {
      scenes.push_back(rad::flatten(rad::load_scene_world(name)));
      auto c = scenes.back().counts();
      auto t = rad::thesis_counts(name);
      auto pair = [](int a, int b) { return fmt::format("{}/{}", a, b); };
      fmt::print("{:<8} {:>11} {:>11} {:>11} {:>11} {:>11}\n", scenes.back().name, pair(c.instances, t.instances),
                 pair(c.surfaces, t.surfaces), pair(c.patches, t.patches), pair(c.elements, t.elements),
                 pair(c.vertices, t.vertices));
    }
    fmt::print("\ntable 4.2: loops ({} shooters each) to shoot a fraction of the energy (this / thesis)\n", f->shooters);
    fmt::print("{:>8}", "energy%");
    for (const auto& s : scenes) fmt::print(" {:>13}", s.name);
    fmt::print("\n");
    std::vector<std::vector<int>> loops(scenes.size());
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      rad::SolverOptions o;
      o.hemicube.resolution = f->hemicube;
      o.shooters = f->shooters;
      o.energy = rad::thesis::kEnergyPercent.back() / 100;
      auto r = rad::solve_progressive(scenes[i], o);
      for (double pct : rad::thesis::kEnergyPercent) {
        int l = -1;
        for (const auto& st : r.steps)
          if (st.shot_fraction >= pct / 100) {
            l = st.step;
            break;
          }
        loops[i].push_back(l);
      }
    }
    std::ofstream csv;
    if (!f->csv.empty()) {
      csv.open(f->csv);
      if (!csv) throw std::runtime_error("cannot write CSV file '" + f->csv + "'");
      csv << "energy_percent";
      for (const auto& s : scenes) csv << ',' << s.name << ',' << s.name << "_thesis";
      csv << '\n';
    }
    for (std::size_t k = 0; k < rad::thesis::kEnergyPercent.size(); ++k) {
      fmt::print("{:>8}", rad::thesis::kEnergyPercent[k]);
      if (csv) csv << rad::thesis::kEnergyPercent[k];
      for (std::size_t i = 0; i < scenes.size(); ++i) {
        const auto* fig = rad::thesis::figures_for(scenes[i].name);
        int t = fig ? fig->loops_for_energy[k] : -1;
        auto num = [](int v) { return v < 0 ? std::string("-") : fmt::format("{}", v); };
        fmt::print(" {:>13}", num(loops[i][k]) + " / " + num(t));
        if (csv) csv << ',' << (loops[i][k] < 0 ? "" : num(loops[i][k])) << ',' << (t < 0 ? "" : num(t));
      }
      fmt::print("\n");
      if (csv) csv << '\n';
    }
    if (!f->csv.empty()) fmt::print("csv {}\n", f->csv);
  });
}

void add_scene_info(CommandGroups& g) {
  struct Flags {
    std::string scene;
    std::string export_dir;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = g.scene->add_subcommand(
      "info",
      "Print a scene's counts of instances, surfaces, patches, elements and vertices (the columns of the\n"
      "thesis's table 4.1), next to the thesis's figures for the built-in scenes.");
  cmd->add_option("scene", f->scene, "room, picroom, cornell or the path of a WORLD file")->required();
  cmd->add_option("--export", f->export_dir, "Also write the scene as WORLD and ENTITY files into this directory");
  cmd->callback([f] {
    rad::World world = rad::load_scene_world(f->scene);
    rad::Scene scene = rad::flatten(world);
    auto c = scene.counts();
    auto t = rad::thesis_counts(f->scene);
    if (t.instances == 0) t = rad::thesis_counts(scene.name);  // an exported built-in scene keeps its name
    fmt::print("scene {} ({})\n", scene.name, f->scene);
    fmt::print("{:<10} {:>9} {:>9} {:>8} {:>9} {:>9}\n", "", "instances", "surfaces", "patches", "elements", "vertices");
    fmt::print("{:<10} {:>9} {:>9} {:>8} {:>9} {:>9}\n", "this", c.instances, c.surfaces, c.patches, c.elements, c.vertices);
    if (t.instances > 0)
      fmt::print("{:<10} {:>9} {:>9} {:>8} {:>9} {:>9}   {}\n", "thesis", t.instances, t.surfaces, t.patches, t.elements,
                 t.vertices, t == c ? "(equal)" : "(DIFFERENT)");
    rad::Vec3 lo = scene.vertices.at(0), hi = lo;
    for (const auto& v : scene.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    fmt::print("bounds    ({:g}, {:g}, {:g}) .. ({:g}, {:g}, {:g})\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    double emitted = 0;
    int lights = 0;
    for (const auto& p : scene.patches)
      if (rad::channel_sum(scene.surfaces[p.surface].exitance) > 0) {
        ++lights;
        emitted += rad::channel_sum(scene.surfaces[p.surface].exitance) * p.area;
      }
    fmt::print("lights    {} emitting patches, emitted energy (r+g+b) {:g}\n", lights, emitted);
    if (scene.camera)
      fmt::print("camera    eye ({:g}, {:g}, {:g}) target ({:g}, {:g}, {:g}) fov {:g}\n", scene.camera->eye.x,
                 scene.camera->eye.y, scene.camera->eye.z, scene.camera->target.x, scene.camera->target.y,
                 scene.camera->target.z, scene.camera->fov_y_degrees);
    if (!f->export_dir.empty()) {
      std::filesystem::create_directories(f->export_dir);
      std::vector<std::string> names;
      for (std::size_t i = 0; i < world.entities.size(); ++i) {
        std::string name = fmt::format("entity{}.ent", i);
        std::ofstream(std::filesystem::path(f->export_dir) / name) << rad::format_entity(world.entities[i]);
        names.push_back(name);
      }
      std::string wname = fmt::format("{}.wld", f->scene.find('/') == std::string::npos ? f->scene : "scene");
      std::ofstream(std::filesystem::path(f->export_dir) / wname) << rad::format_world(world, names);
      fmt::print("exported  {}/{}\n", f->export_dir, wname);
    }
  });
}

}  // namespace

void add_radiosity_commands(CommandGroups& g) {
  add_run(g);
  add_sweep(g);
  add_accuracy(g);
  add_table(g);
  add_scene_info(g);
}

}  // namespace gcsim::cli
