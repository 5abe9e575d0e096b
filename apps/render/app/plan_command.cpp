// gcsim plan SCENE.toml [--nodes N] [--config F] [--json F]: the passes a scene needs, each on or
// off with the reason, and an estimate of its simulated time and memory per node.
#include <memory>

#include <fmt/format.h>

#include "apps/common/scene/scene_file.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/render/app/render_commands.hpp"
#include "apps/render/plan_report.hpp"
#include "apps/render/radiosity_sample.hpp"

namespace gcsim::render::app {

namespace {
struct PlanFlags {
  std::string scene;
  pipeline::MachineOptions machine;
  int sample_loops = 16;
};
}  // namespace

void add_plan_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<PlanFlags>();
  CLI::App* cmd = g.app->add_subcommand(
      "plan",
      "Decide from a scene file alone which passes a render needs (view, radiosity, specular ray tracing,\n"
      "media, shadows), say why each is on or off, and estimate each pass's simulated time and memory per\n"
      "node on the chosen machine before anything runs.");
  cmd->add_option("scene", f->scene, "a TOML scene file (see scenes/ and apps/common/scene/README.md)")->required();
  cmd->add_option("--nodes", f->machine.nodes, "nodes the estimate is for (default 1)")->check(CLI::PositiveNumber);
  cmd->add_option("--config", f->machine.config, "machine file (default: the built-in GC-PowerPlus)");
  cmd->add_option("--json", f->machine.json, "also write the plan as JSON to this file");
  cmd->add_option("--model", f->machine.model, "network model of the radiosity sample: analytic, flow or packet");
  cmd->add_option("--sample-loops", f->sample_loops,
                  "radiosity loops run on the simulated machine to measure a loop's time (communication\n"
                  "included); 0: count operations only, as for the other passes")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->callback([f] {
    const scene::SceneDescription d = scene::load_scene_file(f->scene);
    const machine::MachineConfig machine = pipeline::simulation_options(f->machine, 1).config;
    const int nodes = f->machine.nodes > 0 ? f->machine.nodes : 1;
    const Plan plan = make_plan(d);
    CostModel model;
    if (plan.pass(PassId::radiosity).on && f->sample_loops > 0) {
      const RadiositySample s =
          sample_radiosity_loops(d, f->scene, pipeline::simulation_options(f->machine, nodes), f->sample_loops);
      model.radiosity_seconds_per_loop = s.seconds_per_loop;
      model.radiosity_loops = s.expected_loops;
    }
    fmt::print("{}", format_plan(plan, machine, nodes, model));
    if (!f->machine.json.empty()) pipeline::write_json_file(f->machine.json, plan_json(plan, machine, nodes, model));
  });
}

}  // namespace gcsim::render::app
