// gcsim table radiosity: the thesis's tables 4.1 (scene counts) and 4.2 (loops per energy fraction)
// next to the published figures.
#include <exception>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/radiosity/app/commands.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/progressive_solver.hpp"
#include "apps/radiosity/thesis_tables.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::radiosity::app {

namespace {

struct TableFlags {
  int hemicube = 256;
  int shooters = 2;
  std::string csv;
};

std::vector<Scene> print_table_4_1() {
  fmt::print("table 4.1: scenes ({} / thesis)\n", "this");
  fmt::print("{:<8} {:>11} {:>11} {:>11} {:>11} {:>11}\n", "scene", "instances", "surfaces", "patches", "elements", "vertices");
  std::vector<Scene> scenes;
  for (const auto& name : builtin_scene_names()) {
    scenes.push_back(flatten(load_scene_world(name)));
    const auto c = scenes.back().counts();
    const auto t = thesis_counts(name);
    auto pair = [](int a, int b) { return fmt::format("{}/{}", a, b); };
    fmt::print("{:<8} {:>11} {:>11} {:>11} {:>11} {:>11}\n", scenes.back().name, pair(c.instances, t.instances),
               pair(c.surfaces, t.surfaces), pair(c.patches, t.patches), pair(c.elements, t.elements),
               pair(c.vertices, t.vertices));
  }
  return scenes;
}

// Loops needed to reach each of the thesis's energy percentages (-1: not reached).
std::vector<int> loops_per_energy(const Scene& scene, const TableFlags& f) {
  SolverOptions o;
  o.hemicube.resolution = f.hemicube;
  o.shooters = f.shooters;
  o.energy = thesis::kEnergyPercent.back() / 100;
  // A host-side solve: it polls SIGINT/SIGTERM itself, a loop apart (exit 130, table 4.1 printed).
  const auto r = solve_progressive(scene, o, nullptr, [](const StepRecord&, const ProgressiveState&) {
    parix::host::throw_if_interrupted();
  });
  std::vector<int> loops;
  for (double pct : thesis::kEnergyPercent) {
    int l = -1;
    for (const auto& st : r.steps)
      if (st.shot_fraction >= pct / 100) {
        l = st.step;
        break;
      }
    loops.push_back(l);
  }
  return loops;
}

void print_table_4_2(const std::vector<Scene>& all_scenes, const TableFlags& f) {
  fmt::print("\ntable 4.2: loops ({} shooters each) to shoot a fraction of the energy (this / thesis)\n", f.shooters);
  // Interrupted (SIGINT/SIGTERM), the scenes already solved are still printed and written.
  std::vector<std::vector<int>> loops;
  std::exception_ptr interrupted;
  try {
    for (const Scene& s : all_scenes) loops.push_back(loops_per_energy(s, f));
  } catch (const parix::host::Interrupted&) {
    interrupted = std::current_exception();
  }
  const std::vector<Scene> scenes(all_scenes.begin(), all_scenes.begin() + std::ptrdiff_t(loops.size()));
  fmt::print("{:>8}", "energy%");
  for (const auto& s : scenes) fmt::print(" {:>13}", s.name);
  fmt::print("\n");
  std::ofstream csv;
  if (!f.csv.empty()) {
    csv.open(f.csv);
    if (!csv) throw std::runtime_error("cannot write CSV file '" + f.csv + "'");
    csv << "energy_percent";
    for (const auto& s : scenes) csv << ',' << s.name << ',' << s.name << "_thesis";
    csv << '\n';
  }
  auto num = [](int v) { return v < 0 ? std::string("-") : fmt::format("{}", v); };
  for (std::size_t k = 0; k < thesis::kEnergyPercent.size(); ++k) {
    fmt::print("{:>8}", thesis::kEnergyPercent[k]);
    if (csv) csv << thesis::kEnergyPercent[k];
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const auto* fig = thesis::figures_for(scenes[i].name);
      const int t = fig ? fig->loops_for_energy[k] : -1;
      fmt::print(" {:>13}", num(loops[i][k]) + " / " + num(t));
      if (csv) csv << ',' << (loops[i][k] < 0 ? "" : num(loops[i][k])) << ',' << (t < 0 ? "" : num(t));
    }
    fmt::print("\n");
    if (csv) csv << '\n';
  }
  if (!f.csv.empty()) fmt::print("csv {}\n", f.csv);
  if (interrupted) {
    fmt::print("interrupted: {} of {} scenes solved\n", scenes.size(), all_scenes.size());
    std::rethrow_exception(interrupted);
  }
}

}  // namespace

void add_table_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<TableFlags>();
  CLI::App* cmd = g.table->add_subcommand(
      "radiosity",
      "The thesis's tables 4.1 (scene counts) and 4.2 (progressive-refinement loops needed to shoot a\n"
      "given fraction of the energy) for ROOM, PICROOM and CORNELL, next to the published figures.\n"
      "Loop counts come from the sequential solver (they do not depend on the node count).");
  cmd->add_option("--hemicube", f->hemicube, "Hemicube resolution")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--shooters", f->shooters, "Shooters per loop (the thesis: 2)")->check(CLI::Range(1, 1 << 20))->capture_default_str();
  cmd->add_option("--csv", f->csv, "Write table 4.2 as CSV");
  cmd->callback([f] { print_table_4_2(print_table_4_1(), *f); });
}

}  // namespace gcsim::radiosity::app
