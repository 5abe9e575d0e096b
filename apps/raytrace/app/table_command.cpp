// gcsim table raytrace: the paper's tables 1 (algorithms x scenes) and 2 (A4 against subregion
// size), ours beside the paper's.
#include <cmath>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/raytrace/algorithm.hpp"
#include "apps/raytrace/app/commands.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/cost_model.hpp"
#include "apps/raytrace/paper_figures.hpp"
#include "apps/raytrace/render.hpp"
#include "machine/machine_config.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::raytrace::app {

namespace {

struct Measured {
  TraceCounters counters;
  double simulated = 0;  // seconds on one CPU of the machine
  double wall = 0;
};

Measured measure(const Scene& scene, const Bvh& bvh, Algorithm a, int tile, int size, const machine::MachineConfig& config) {
  // Host-side renders: SIGINT/SIGTERM is polled here, one image apart (the CSV keeps the rows done).
  parix::host::throw_if_interrupted();
  RenderSettings rs;
  rs.algorithm = a;
  rs.tile = tile;
  rs.width = rs.height = size;
  rs.shading = Shading::local;
  const RenderOutput out = render_image(scene, bvh, rs);
  return {out.counters, machine::to_seconds(single_cpu_time(out.counters, config)), out.wall_seconds};
}

std::string paper_value(double v, int decimals) { return v < 0 ? "-" : fmt::format("{:.{}f}", v, decimals); }
std::string min_sec(double s) { return fmt::format("{}'{:02d}\"", int(s) / 60, int(std::lround(s)) % 60); }

struct TableFlags {
  int size = 512;
  int tile = 8;
  std::string which = "both";
  std::string csv;  // empty: no CSV (like every other command, files only on request)
  std::string config;
};

void print_table_1(const TableFlags& f, const machine::MachineConfig& config, const std::vector<Scene>& scenes,
                 const std::vector<Bvh>& bvhs) {
  fmt::print("Table 1: primary rays, {}x{}, {}x{} subregions. Time: paper sun4/260 | ours, simulated on one {:.0f} MHz GC CPU "
             "(host wall).\nBV and prim: tests per ray; total: all tests over the image, thousands. Paper | ours.\n\n",
             f.size, f.size, f.tile, f.tile, config.clock_hz / 1e6);
  std::ofstream csv;
  if (!f.csv.empty()) {
    csv.open(f.csv + "1.csv");
    if (!csv) throw std::runtime_error("cannot write " + f.csv + "1.csv");
    csv << "algorithm,scene,photo,paper_time_s,sim_time_s,wall_time_s,paper_bv_per_ray,bv_per_ray,paper_prim_per_ray,"
           "prim_per_ray,paper_total_k,total_k,plane_tests,uniform_regions,uniformity_box_checks\n";
  }
  fmt::print("{:<4} {:<15} {:>8} {:>9} {:>8}  {:>6} {:>6}  {:>6} {:>6}  {:>7} {:>7}\n", "alg", "scene", "paper", "sim s",
             "wall s", "BV", "", "prim", "", "total", "");
  for (const auto& row : paper::kTable1) {
    const Algorithm a = *parse_algorithm(row.algorithm);
    for (int s = 0; s < 5; ++s) {
      const Measured m = measure(scenes[s], bvhs[s], a, f.tile, f.size, config);
      const double rays = double(m.counters.primary_rays);
      const double bv = m.counters.primary_box_tests / rays, prim = m.counters.primary_prim_tests / rays;
      const double total = (m.counters.primary_box_tests + m.counters.primary_prim_tests) / 1e3;
      fmt::print("{:<4} {:<15} {:>8} {:>9.3f} {:>8.3f}  {:>6} {:>6.2f}  {:>6} {:>6.2f}  {:>7.0f} {:>7.0f}\n", row.algorithm,
                 paper::kScenes[s], min_sec(row.seconds[s]), m.simulated, m.wall, paper_value(row.bv_per_ray[s], 2),
                 bv, paper_value(row.prim_per_ray[s], 2), prim, row.total_thousands[s], total);
      if (csv.is_open())
        csv << fmt::format("{},{},{},{},{:.6f},{:.6f},{},{:.4f},{},{:.4f},{},{:.1f},{},{},{}\n", row.algorithm, paper::kScenes[s],
                           paper::kPhotos[s], row.seconds[s], m.simulated, m.wall,
                           row.bv_per_ray[s] < 0 ? "" : fmt::format("{}", row.bv_per_ray[s]), bv, row.prim_per_ray[s], prim,
                           row.total_thousands[s], total, m.counters.plane_tests, m.counters.uniform_regions,
                           m.counters.uniformity_box_checks);
    }
    fmt::print("\n");
  }
  if (csv.is_open()) fmt::print("csv       {}1.csv\n\n", f.csv);
}

void print_table_2(const TableFlags& f, const machine::MachineConfig& config, const std::vector<Scene>& scenes,
                 const std::vector<Bvh>& bvhs) {
  fmt::print("Table 2: A4 time against subregion size. Paper sun4/260 | ours simulated on one GC CPU (s).\n\n");
  std::ofstream csv;
  if (!f.csv.empty()) {
    csv.open(f.csv + "2.csv");
    if (!csv) throw std::runtime_error("cannot write " + f.csv + "2.csv");
    csv << "tile,scene,photo,paper_time_s,sim_time_s,wall_time_s,bv_per_ray,prim_per_ray,plane_tests\n";
  }
  fmt::print("{:<6}", "tile");
  for (auto name : paper::kScenes) fmt::print(" {:>20}", name);
  fmt::print("\n");
  for (const auto& row : paper::kTable2) {
    fmt::print("{:<6}", fmt::format("{}x{}", row.tile, row.tile));
    for (int s = 0; s < 5; ++s) {
      const Measured m = measure(scenes[s], bvhs[s], Algorithm::A4, row.tile, f.size, config);
      fmt::print(" {:>9} | {:>8.3f}", min_sec(row.seconds[s]), m.simulated);
      const double rays = double(m.counters.primary_rays);
      if (csv.is_open())
        csv << fmt::format("{},{},{},{},{:.6f},{:.6f},{:.4f},{:.4f},{}\n", row.tile, paper::kScenes[s], paper::kPhotos[s],
                           row.seconds[s], m.simulated, m.wall, m.counters.primary_box_tests / rays,
                           m.counters.primary_prim_tests / rays, m.counters.plane_tests);
    }
    fmt::print("\n");
  }
  if (csv.is_open()) fmt::print("\ncsv       {}2.csv\n", f.csv);
}

}  // namespace

void add_table_command(pipeline::CommandGroups& g) {
  auto o = std::make_shared<TableFlags>();
  CLI::App* cmd = g.table->add_subcommand(
      "raytrace",
      "The paper's table 1 (6 algorithms x 5 scenes: time, BV and primitive tests per ray, total tests) and\n"
      "table 2 (A4 time against subregion size), ours beside the paper's. Our time is the simulated time of\n"
      "one GC-PowerPlus CPU (PowerPC 601) from the counted operations; the paper's is a sun4/260's. Counts\n"
      "are exact. Expect the paper's ordering: A1 the most tests, A2' far fewer than A1, A4 the fewest BV tests.");
  cmd->add_option("--size", o->size, "Image width and height (the paper: 512)")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--tile", o->tile, "Subregion size of table 1 (the paper: 8)")->check(CLI::Range(2, 512))->capture_default_str();
  cmd->add_option("--which", o->which, "1, 2 or both")->check(CLI::IsMember({"1", "2", "both"}))->capture_default_str();
  cmd->add_option("--csv", o->csv, "Write PREFIX1.csv and PREFIX2.csv (e.g. --csv raytrace_table; default: no CSV)");
  pipeline::add_config_option(cmd, o->config, "Machine file whose [ops] costs and clock give the time");
  cmd->callback([o] {
    const machine::MachineConfig config = o->config.empty() ? machine::default_machine_config() : machine::load_machine_config(o->config);
    std::vector<Scene> scenes;
    std::vector<Bvh> bvhs;
    for (auto name : paper::kScenes) {
      scenes.push_back(make_builtin_scene(name));
      bvhs.push_back(build_bvh_by_clustering(scenes.back()));
    }
    if (o->which != "2") print_table_1(*o, config, scenes, bvhs);
    if (o->which != "1") print_table_2(*o, config, scenes, bvhs);
  });
}

}  // namespace gcsim::raytrace::app
