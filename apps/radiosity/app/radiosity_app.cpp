// Registers the radiosity application (thesis chapters 3 and 4) with the gcsim pipeline.
#include <memory>

#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/radiosity/app/commands.hpp"
#include "apps/radiosity/app/radiosity_experiment.hpp"

namespace gcsim::radiosity::app {

namespace {

void add_run_outputs(CLI::App& cmd, RunOutputs& f) {
  cmd.add_option("--image", f.image, "Write a PNG: Z-buffer, radiosities interpolated at vertices (Gouraud)");
  cmd.add_option("--camera", f.camera, "Camera as ex,ey,ez,tx,ty,tz[,fov_y_degrees]; default: the scene's own");
  cmd.add_option("--width", f.width, "Image width (default 512)")->check(CLI::Range(8, 8192));
  cmd.add_option("--height", f.height, "Image height (default 512, 384 for the rooms)")->check(CLI::Range(8, 8192));
  cmd.add_option("--exposure", f.exposure,
                 "Multiply radiosities by this (a positive number) before display; default: automatic (the 97th "
                 "percentile of lit pixels shows at 0.85)")
      ->check(pipeline::positive_number());
  cmd.add_option("--steps-csv", f.steps_csv, "Write the shot fraction after every loop as CSV (table 4.2 analog)");
  cmd.add_option("--radiosities", f.radiosities,
                 "Write every element's radiosity (id, patch, surface, area, r, g, b): FILE.json as JSON, else CSV");
  pipeline::add_list_option(&cmd, "--snapshots", f.snapshots,
                 "With --image: also write the image after these loops (e.g. 1,10,50), as IMAGE_loopN.png: "
                 "the progression of figures 4.10-4.12");
  cmd.add_flag("--gauss-seidel", f.gauss_seidel,
               "Also solve with full-matrix Gauss-Seidel (3.5.1) on the host and print how far the progressive "
               "result is from it (small scenes only)");
}

pipeline::ExperimentFactory declare_options(CLI::App& cmd, pipeline::Verb verb) {
  struct Flags {
    SolveFlags solve;
    RunOutputs outputs;
  };
  auto f = std::make_shared<Flags>();
  add_solve_options(&cmd, f->solve);
  if (verb == pipeline::Verb::run) {
    add_run_outputs(cmd, f->outputs);
    f->outputs.progress = true;
  }
  // Called after parsing, when cmd knows which options were given.
  return [f, &cmd] {
    apply_preset(cmd, f->solve);
    return std::make_unique<RadiosityExperiment>(f->solve, f->outputs);
  };
}

pipeline::AppSpec radiosity_app() {
  pipeline::AppSpec s;
  s.name = "radiosity";
  s.summary =
      "Progressive-refinement radiosity (thesis ch. 3-4) on the simulated GC.\n\n"
      "Each loop the K patches with the most unshot energy (delta B * A) shoot: a hemicube on each\n"
      "patch gives the form factors to every element by Z-buffering (eqs. 3.19-3.21), and every element\n"
      "receives rho * delta B * F * A_patch / A_element. Patches shoot, elements receive. The run stops\n"
      "when the shot fraction of the emitted energy reaches --energy.\n\n"
      "On N nodes every node keeps a replica of the scene; --parallel picks how the work is split and\n"
      "--bcast/--aggregate how the results are exchanged. Every variant gives the same radiosities as\n"
      "one node. The run prints simulated seconds (what the GC would take) next to wall seconds.";
  s.run_footer =
      "\nExamples:\n"
      "  gcsim run radiosity --scene cornell --nodes 8 --json r.json --image c.png\n"
      "  gcsim run radiosity --scene room --nodes 16 --bcast tree --steps-csv loops.csv\n"
      "  gcsim run radiosity --scene picroom --parallel hemicube-hierarchical --levels 2 --nodes 8\n"
      "  gcsim run radiosity --scene cornell --nodes 8 --order index --max-steps 2000   (thesis 4.4.1)\n"
      "  gcsim run radiosity --scene tests/radiosity/fixtures/opposing_squares_lit.wld --energy 0.99999";
  s.examples = {"gcsim run radiosity --scene cornell --nodes 8  parallel radiosity, thesis ch. 4",
                "gcsim sweep radiosity --scene cornell --jobs 2  node counts 1..64, two simulations at a time"};
  s.sweep_summary =
      "Run radiosity for several node counts and print, per count, simulated seconds, speedup over the\n"
      "first count, simulated communication seconds (mean per node) and wall seconds, next to the\n"
      "thesis's tables 4.3/4.4/4.5 (sequential broadcast) or 4.8 (tree broadcast) for built-in scenes.\n"
      "The thesis's shape: time falls with more nodes at first, then rises as communication dominates.";
  s.sweep_footer =
      "\nExamples:\n"
      "  gcsim sweep radiosity --scene cornell\n"
      "  gcsim sweep radiosity --scene cornell --bcast tree --csv tree.csv\n"
      "  gcsim sweep radiosity --scene cornell --preset thesis   (the thesis's program: tables 4.3-4.5)\n"
      "  gcsim sweep radiosity --scene room --aggregate --nodes 1,8,64 --jobs 2";
  s.default_nodes = 1;
  s.options = declare_options;
  s.commands = [](pipeline::CommandGroups& g) {
    add_accuracy_command(g);
    add_table_command(g);
    add_scene_info_command(g);
  };
  return s;
}

const pipeline::AppRegistrar registrar{radiosity_app()};

}  // namespace

}  // namespace gcsim::radiosity::app
