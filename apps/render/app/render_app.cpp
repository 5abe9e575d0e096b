// The render app: `gcsim plan SCENE.toml` (plan_command.cpp) and `gcsim run render --scene
// SCENE.toml`, which runs the plan's passes that the unified renderer has so far: the radiosity
// pass (the thesis's parallel progressive refinement on the scene's polygons). The view, specular,
// media and shadow passes are planned but not yet run here.
#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/common/image.hpp"
#include "apps/radiosity/gouraud_renderer.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/scene.hpp"
#include "apps/render/app/render_commands.hpp"
#include "apps/render/plan.hpp"

namespace gcsim::render::app {

namespace {

struct RenderOutcome : pipeline::Outcome {
  radiosity::ParallelOutcome radiosity;  // node 0's replica after the run
  std::unique_ptr<pipeline::ProgressLine> progress;
  int loops_done = 0;          // the radiosity pass as processor 0 reported it: what an
  double shot_fraction = 0.0;  // interrupted run reached
};

class RenderExperiment : public pipeline::Experiment {
 public:
  RenderExperiment(const std::string& scene_file, std::string image, bool progress)
      : description_(scene::load_scene_file(scene_file)), plan_(make_plan(description_)), image_(std::move(image)),
        progress_(progress) {
    if (plan_.pass(PassId::radiosity).on) mesh_ = radiosity::flatten(scene::to_world(description_));
    options_.solver.hemicube.resolution = 256;  // `gcsim run radiosity`'s default
  }
  std::unique_ptr<pipeline::Outcome> new_outcome(int) const override { return std::make_unique<RenderOutcome>(); }
  parix::Program program(pipeline::Outcome& out) const override {
    if (!plan_.pass(PassId::radiosity).on) return [](parix::Processor&) {};
    RenderOutcome& o = pipeline::outcome_as<RenderOutcome>(out);
    radiosity::ParallelOutcome* result = &o.radiosity;
    if (progress_ && pipeline::progress_wanted()) o.progress = std::make_unique<pipeline::ProgressLine>("render", 0);
    radiosity::ParallelOptions shown = radiosity::with_shared_projections(options_);
    // As `gcsim run radiosity`'s line: unshot energy falls about geometrically per loop.
    shown.on_loop = [&o, goal = std::log(1 - options_.solver.energy)](int loop, double shot) {
      o.loops_done = loop, o.shot_fraction = shot;
      if (!o.progress) return;
      const double fraction = goal < 0 ? std::clamp(std::log(std::max(1 - shot, 1e-300)) / goal, 0.0, 1.0) : 1.0;
      o.progress->update_fraction(fraction, fmt::format("radiosity pass: loop {}, {:.4f}% of the energy shot", loop, 100 * shot));
    };
    return [this, result, shown](parix::Processor& p) { radiosity::radiosity_program(p, mesh_, shown, result); };
  }
  void after_run(pipeline::Outcome& out) const override {
    pipeline::outcome_as<RenderOutcome>(out).progress.reset();  // erases the line before the report
  }
  void report_interrupted(const pipeline::Outcome& out, nlohmann::json& reached) const override {
    const auto& o = pipeline::outcome_as<RenderOutcome>(out);
    reached["radiosity_loops"] = o.loops_done;
    reached["radiosity_shot_fraction"] = o.shot_fraction;
  }
  void print_setup(int nodes) const override {
    fmt::print("scene     {}: {} patches, {} elements\n", plan_.scene_name, plan_.facts.patches, plan_.facts.elements);
    for (const PassPlan& p : plan_.passes) {
      const bool runs = p.on && p.id == PassId::radiosity;
      fmt::print("pass      {:<10} {}\n", pass_name(p.id),
                 !p.on ? "off (gcsim plan says why)" : runs ? fmt::format("runs on {} nodes", nodes) : "planned, not yet run");
    }
  }
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override {
    const auto& r = pipeline::outcome_as<RenderOutcome>(out).radiosity;
    if (!plan_.pass(PassId::radiosity).on) {
      fmt::print("radiosity skipped: {}\n", plan_.pass(PassId::radiosity).reason);
      extra["radiosity"] = {{"ran", false}};
      if (!image_.empty()) fmt::print("image     not written: only the radiosity pass renders so far, and it is off\n");
      return;
    }
    fmt::print("radiosity {} steps, {}converged\n", r.steps.size(), r.converged ? "" : "not ");
    extra["radiosity"] = {{"ran", true}, {"steps", r.steps.size()}, {"converged", r.converged},
                          {"elements", r.element_radiosity.size()}};
    if (!image_.empty()) write_image(r);
  }

 private:
  scene::SceneDescription description_;
  Plan plan_;
  radiosity::Scene mesh_;
  radiosity::ParallelOptions options_;
  std::string image_;
  bool progress_;  // gcsim run: a line per loop on a terminal

  // The radiosity solution seen from the scene's camera, Gouraud-shaded on the host (not yet a
  // pass on the simulated nodes).
  void write_image(const radiosity::ParallelOutcome& r) const {
    radiosity::RenderOptions ro;
    ro.width = description_.image.width;
    ro.height = description_.image.height;
    const radiosity::Camera camera = mesh_.camera ? *mesh_.camera : radiosity::default_camera(mesh_);
    apps::write_png(image_, radiosity::render_gouraud(mesh_, r.element_radiosity, camera, ro));
    fmt::print("image     {} (radiosity, Gouraud-shaded on the host)\n", image_);
  }
};

pipeline::AppSpec spec() {
  pipeline::AppSpec s;
  s.name = "render";
  s.summary = "Render a TOML scene file with the passes its plan needs (so far: the radiosity pass).";
  s.examples = {"gcsim plan scenes/cornell.toml --nodes 8  which passes a scene needs, and why"};
  s.run_footer = "Example:\n  gcsim plan scenes/cornell.toml --nodes 8\n  gcsim run render --scene scenes/cornell.toml --nodes 8";
  s.options = [](CLI::App& cmd, pipeline::Verb verb) -> pipeline::ExperimentFactory {
    auto scene = std::make_shared<std::string>();
    auto image = std::make_shared<std::string>();
    cmd.add_option("--scene", *scene, "a TOML scene file (scenes/*.toml)")->required();
    cmd.add_option("--image", *image, "write the radiosity solution seen from the scene's camera as PNG");
    const bool progress = verb == pipeline::Verb::run;
    return [scene, image, progress] { return std::make_unique<RenderExperiment>(*scene, *image, progress); };
  };
  s.commands = [](pipeline::CommandGroups& g) { add_plan_command(g); };
  return s;
}
const pipeline::AppRegistrar registrar{spec()};

}  // namespace
}  // namespace gcsim::render::app
