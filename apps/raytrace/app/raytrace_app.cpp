// Registers the ray tracer (Naruse, Shinya and Saito's dynamic subtrees) with the gcsim pipeline.
#include <memory>

#include "apps/pipeline/app_registry.hpp"
#include "apps/raytrace/app/commands.hpp"
#include "apps/raytrace/app/raytrace_experiment.hpp"

namespace gcsim::raytrace::app {

namespace {

pipeline::ExperimentFactory declare_options(CLI::App& cmd, pipeline::Verb verb) {
  auto f = std::make_shared<RaytraceFlags>();
  add_render_options(&cmd, f->render);
  if (verb == pipeline::Verb::run) {
    cmd.add_option("--distribute", f->distribute,
                   "static: contiguous blocks of tiles per node; interleaved: tile i to node i mod N; "
                   "dynamic: node 0 hands out tiles on request (load balancing)")
        ->check(CLI::IsMember({"static", "interleaved", "dynamic"}))
        ->capture_default_str();
    cmd.add_option("--image", f->image, "Write the image as PNG");
    f->progress = true;
  } else {
    cmd.add_option("--distribute", f->distribute, "static, interleaved or dynamic (see run raytrace --help)")
        ->check(CLI::IsMember({"static", "interleaved", "dynamic"}))
        ->capture_default_str();
  }
  return [f] { return std::make_unique<RaytraceExperiment>(*f); };
}

pipeline::AppSpec raytrace_app() {
  pipeline::AppSpec s;
  s.name = "raytrace";
  s.summary =
      "Ray trace a scene on the simulated GC: the image is cut into subregions (tiles), the tiles are\n"
      "distributed over the nodes, each node traces its tiles with the chosen algorithm and charges the\n"
      "counted ray-box and ray-primitive tests to its CPU, and node 0 assembles the image.\n"
      "Prints the paper's counters (BV and primitive tests per ray) and simulated next to wall time.";
  s.run_footer = "\nExample:\n  gcsim run raytrace --scene teapots --algo A4 --nodes 16 --image t.png --json t.json";
  s.examples = {"gcsim run raytrace --scene teapots --nodes 16  ray tracing by subtrees (A4), the paper's photo 5"};
  s.sweep_summary =
      "Render the same image on 1..64 simulated nodes: simulated time, speedup over 1 node, parallel\n"
      "efficiency, mean communication time per node, and the host's wall time for each run.";
  s.default_nodes = 16;
  s.options = declare_options;
  s.commands = [](pipeline::CommandGroups& g) {
    add_table_command(g);
    add_bench_command(g);
  };
  return s;
}

const pipeline::AppRegistrar registrar{raytrace_app()};

}  // namespace

}  // namespace gcsim::raytrace::app
