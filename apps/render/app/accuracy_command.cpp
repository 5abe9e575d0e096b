// gcsim accuracy render SCENE.toml: what each pass's accuracy costs in time across a whole render.
// Each pass's main control is varied from the default with the others held; every render runs the
// plan on the simulated machine and is compared with a high-quality reference render.
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/pipeline/csv_comment.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/render/app/render_commands.hpp"
#include "apps/render/render_accuracy.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::render::app {

namespace {

struct AccuracyFlags {
  std::string scene, csv;
  pipeline::MachineOptions machine;
  bool quick = false;
};

struct Row {
  std::string pass, control;
  double value, error, simulated_s, wall_s;
};

void print_row(const Row& r) {
  fmt::print("{:<10} {:<9} {:>8g} {:>12.5f} {:>13.3f} {:>9.2f}\n", r.pass, r.control, r.value, r.error, r.simulated_s,
             r.wall_s);
}

void write_csv(const std::string& path, const std::vector<Row>& rows, const machine::MachineConfig& m) {
  std::ofstream out(path);
  if (!out) throw pipeline::FileError(fmt::format("cannot write '{}'", path));
  out << pipeline::csv_comment("accuracy render", m.name, std::to_string(m.nodes), m.network_model) << '\n';
  out << "pass,control,value,relative_rmse,simulated_s,wall_s\n";
  for (const Row& r : rows)
    out << fmt::format("{},{},{},{},{},{}\n", r.pass, r.control, r.value, r.error, r.simulated_s, r.wall_s);
}

void run(const AccuracyFlags& f) {
  pipeline::check_writable(f.csv, "--csv");  // before the renders, which take minutes
  const scene::SceneDescription d = scene::load_scene(f.scene);
  const Plan plan = make_plan(d);
  const parix::SimulationOptions machine = pipeline::simulation_options(f.machine, 8);
  const std::vector<ControlSweep> sweeps = control_sweeps(plan, f.quick);
  if (sweeps.empty())
    fmt::print("{}: no pass with a control runs (no radiosity, specular or media): only the reference is rendered\n", f.scene);
  RenderControls reference = reference_controls();
  if (f.quick) reference.hemicube = 256, reference.photons = 100000;
  fmt::print("reference: hemicube {}, energy {}, depth {}{} on {} nodes ...\n", reference.hemicube, reference.energy,
             reference.max_depth,
             plan.pass(PassId::media).on ? fmt::format(", {} photons, march {}", reference.photons, reference.march) : "",
             machine.config.nodes);
  const RenderRun ref = render_with(d, plan, reference, 0, machine);
  fmt::print("reference: {:.3f} s simulated, {:.2f} s wall; every render below shows at its exposure {:.4g}\n\n",
             ref.simulated_s, ref.wall_s, ref.exposure);
  fmt::print("{:<10} {:<9} {:>8} {:>12} {:>13} {:>9}\n", "pass", "control", "value", "rel. RMSE", "simulated s", "wall s");
  std::vector<Row> rows;
  for (const ControlSweep& s : sweeps)
    for (double v : s.values) {
      parix::host::throw_if_interrupted();
      const RenderRun r = render_with(d, plan, with_control(RenderControls{}, s.control, v), ref.exposure, machine);
      rows.push_back({pass_name(s.pass), s.control, v, relative_rmse(r.image, ref.image), r.simulated_s, r.wall_s});
      print_row(rows.back());
    }
  fmt::print("\nrel. RMSE: root mean square over pixels and channels of (render - reference), over the\n"
             "reference's mean; defaults: hemicube 256, energy 0.999, depth 5, {} photons, march 32\n"
             "(media: distance samples per free path); photons and march samples also vary the noise.\n",
             kDefaultPhotons);
  if (!f.csv.empty()) {
    write_csv(f.csv, rows, machine.config);
    fmt::print("csv       {} (gcsim plot --accuracy {} draws error against simulated time)\n", f.csv, f.csv);
  }
}

}  // namespace

void add_render_accuracy_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<AccuracyFlags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "render",
      "What accuracy costs across a whole render: each pass's main control (radiosity: hemicube resolution,\n"
      "energy fraction; specular: reflection depth; media: photons, march samples per free path) varied from\n"
      "the default with the others held, each render run on the simulated machine, its image's error against\n"
      "a reference (hemicube 512, energy 0.9999, depth 10, 200000 photons, march 128) next to its simulated\n"
      "and wall time.");
  cmd->add_option("scene", f->scene, "a scene file (scenes/*.toml, .obj, .wld) or a built-in scene's name")->required();
  pipeline::add_nodes_option(cmd, f->machine.nodes, "8");
  pipeline::add_config_option(cmd, f->machine.config);
  cmd->add_option("--csv", f->csv, "write pass,control,value,relative_rmse,simulated_s,wall_s");
  cmd->add_flag("--quick", f->quick, "fewer values and a hemicube-256 reference (about a minute on CORNELL)");
  cmd->footer("Example:\n  gcsim accuracy render scenes/cornell-mirror-glass.toml --csv acc.csv && gcsim plot --accuracy acc.csv");
  cmd->callback([f] { run(*f); });
}

}  // namespace gcsim::render::app
