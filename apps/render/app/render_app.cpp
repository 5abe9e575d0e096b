// The render app: `gcsim plan SCENE.toml` (plan_command.cpp) and `gcsim run render --scene
// SCENE.toml`, which runs the plan's passes that the unified renderer has so far, one after the
// other on every node: the media pass (photons, and what the media scatter onto the walls), the
// radiosity pass (the thesis's parallel progressive refinement on the scene's polygons), then the view pass (the ray tracer's parallel render, reading the radiosity
// at diffuse hits and following mirrors and glass: the specular pass; marching through media with
// the media pass's photon map).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/pipeline/run_command.hpp"
#include "apps/common/image.hpp"
#include "apps/common/tone_map.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/app/render_commands.hpp"
#include "apps/render/app/render_progress.hpp"
#include "apps/render/error_budget.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/render_accuracy.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/unified_render.hpp"
#include "apps/raytrace/raytrace.hpp"

namespace gcsim::render::app {

namespace {

// --image and --tone-map.
struct ImageOutput {
  std::string path;
  bool tone_map = false;  // the media app's auto exposure and extended Reinhard curve on the PNG only
};

struct RenderOutcome : pipeline::Outcome {
  std::unique_ptr<RenderProgress> progress;
  int loops_done = 0;          // the radiosity pass as processor 0 reported it: what an
  double shot_fraction = 0.0;  // interrupted run reached
  std::unique_ptr<UnifiedRender> render;
};

class RenderExperiment : public pipeline::Experiment {
 public:
  RenderExperiment(const std::string& scene_file, ImageOutput image, const std::vector<std::string>& forced,
                   double error_budget, std::size_t photons, std::uint64_t seed, bool progress)
      : description_(scene::load_scene(scene_file)), plan_(make_plan(description_)), image_(std::move(image)),
        progress_(progress), scene_file_(scene_file) {
    for (const std::string& name : forced) force(name);
    if (error_budget > 0) budget_ = {error_budget, controls_for_budget(description_, plan_, error_budget)};
    view_.secondary = runs(PassId::specular);
    view_.shadows = runs(PassId::shadows);
    view_.shows_radiosity = !runs_forced(PassId::radiosity);
    const RenderControls controls = budget_ ? budget_->choice.controls : RenderControls{};
    photons_ = photons;
    seed_ = seed;
    setup_ = prepare_render(description_, plan_, scene_file,
                            {.media = runs_forced(PassId::media), .radiosity = runs_forced(PassId::radiosity)}, photons,
                            controls.media, seed);
    options_.solver.hemicube.resolution = controls.hemicube;  // `gcsim run radiosity`'s default 256
    options_.solver.energy = controls.energy;
    options_.solver.media = setup_.radiosity_media_or_null();
    view_.max_depth = controls.max_depth;
  }
  std::unique_ptr<pipeline::Outcome> new_outcome(int nodes) const override {
    auto o = std::make_unique<RenderOutcome>();
    o->render = std::make_unique<UnifiedRender>(nodes);
    return o;
  }
  parix::Program program(pipeline::Outcome& out) const override {
    RenderOutcome& o = pipeline::outcome_as<RenderOutcome>(out);
    if (progress_ && pipeline::progress_wanted()) {
      std::array<bool, 5> running{};
      for (const PassPlan& p : plan_.passes) running[static_cast<std::size_t>(p.id)] = runs(p.id);
      running[static_cast<std::size_t>(PassId::media)] = setup_.media && setup_.media->photon_pass;
      o.progress = std::make_unique<RenderProgress>(
          render_stages(plan_, running, o.options.simulation.config, o.options.simulation.config.nodes, int(photons_)));
    }
    radiosity::ParallelOptions shown = radiosity::with_shared_projections(options_, o.options);
    // As `gcsim run radiosity`'s line: unshot energy falls about geometrically per loop.
    shown.on_loop = [&o, goal = std::log(1 - options_.solver.energy)](int loop, double shot) {
      o.loops_done = loop, o.shot_fraction = shot;
      if (!o.progress) return;
      const double fraction = goal < 0 ? std::clamp(std::log(std::max(1 - shot, 1e-300)) / goal, 0.0, 1.0) : 1.0;
      o.progress->update(RenderStage::radiosity, fraction,
                         fmt::format("loop {}, {:.4f}% of the energy shot", loop, 100 * shot));
    };
    const radiosity::Scene* mesh = setup_.mesh_or_null();
    UnifiedRender* render = o.render.get();
    if (o.progress) {
      render->on_view_tile = [&o](int done, int total) {
        o.progress->update(RenderStage::view, double(done) / total, fmt::format("tile {} of {}", done, total));
      };
      render->on_photons = [&o](std::uint64_t traced, std::uint64_t total) {
        o.progress->update(RenderStage::photons, double(traced) / double(total),
                           fmt::format("{} of {} photons traced", traced, total));
      };
    }
    ViewSettings view = view_;
    view.host_threads = shown.host_threads;  // the run's, on the simulated backend
    return [this, render, mesh, shown, view](parix::Processor& p) {
      unified_render_program(p, setup_.split.surfaces, mesh, shown, view, setup_.media.get(), *render);
    };
  }
  void after_run(pipeline::Outcome& out) const override {
    RenderOutcome& o = pipeline::outcome_as<RenderOutcome>(out);
    if (o.progress) o.progress->finish();  // 100 %, once, before the report
    o.progress.reset();
    finish(*o.render);
  }
  void report_interrupted(const pipeline::Outcome& out, nlohmann::json& reached) const override {
    const auto& o = pipeline::outcome_as<RenderOutcome>(out);
    reached["radiosity_loops"] = o.loops_done;
    reached["radiosity_shot_fraction"] = o.shot_fraction;
  }
  pipeline::RunInputs run_inputs() const override {
    pipeline::RunInputs in;
    in.scene = scene_file_, in.seeds = {{"seed", seed_}};
    if (!image_.path.empty()) in.outputs.push_back(image_.path);
    return in;
  }
  void print_setup(int nodes) const override {
    fmt::print("scene     {}: {} patches, {} elements\n", plan_.scene_name, plan_.facts.patches, plan_.facts.elements);
    for (const PassPlan& p : plan_.passes) {
      const bool forced = std::ranges::find(forced_, p.id) != forced_.end();
      fmt::print("pass      {:<10} {}\n", pass_name(p.id),
                 !runs(p.id) ? "off (gcsim plan says why)"
                             : fmt::format("runs on {} nodes{}", nodes, forced ? " (forced on: the plan has it off)" : ""));
    }
  }
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override {
    const auto& o = pipeline::outcome_as<RenderOutcome>(out);
    const UnifiedRender& u = *o.render;
    const double radiosity_s = u.radiosity_seconds();
    // Under MPI the clocks are this rank's wall clock, and only this rank's pass end is known here.
    const bool real = o.run.clock == parix::Clock::wall;
    // The highest any node held (the run's JSON has it only when a node went over its memory):
    // what `gcsim plan`'s memory per node predicts.
    if (!real) extra["memory_peak"] = {{"bytes", o.run.memory_peak}, {"processor", o.run.memory_peak_processor}};
    report_media(u, real, extra);  // the photons run first: radiosity receives what they leave on the walls
    if (!runs(PassId::radiosity)) {
      fmt::print("radiosity skipped: {}\n", plan_.pass(PassId::radiosity).reason);
      extra["radiosity"] = {{"ran", false}};
    } else {
      const auto& r = u.radiosity;
      fmt::print("radiosity {} steps, {}converged; the pass ended at {:.6f} s {}\n", r.steps.size(),
                 r.converged ? "" : "not ", radiosity_s, real ? "of wall time (this rank)" : "simulated (last node)");
      extra["radiosity"] = {{"ran", true}, {"steps", r.steps.size()}, {"converged", r.converged},
                            {"elements", r.element_radiosity.size()}, {"simulated_end_s", radiosity_s}};
      if (setup_.radiosity_media_or_null()) report_radiosity_media(u, extra["radiosity"]);
      if (runs_forced(PassId::radiosity)) report_forced_radiosity(u, extra["radiosity"]);
    }
    if (!u.view) return;
    const double view_start_s = u.view_start_seconds();
    const raytrace::ParallelRender& v = u.view->result;
    const double total_s = o.run.simulated_seconds();
    fmt::print("view      {} x {} pixels, {} primitives, {} shading rays; {:.6f} s {}{}\n", u.view->settings.width,
               u.view->settings.height, u.view->scene.prim_count(), v.counters.shades, total_s - view_start_s,
               real ? "of wall time" : "simulated", view_start_s > 0 ? " after the passes before it" : "");
    if (v.counters.media_segments > 0)
      fmt::print("          {} ray segments through media, {} distance samples ({} nearest photons each)\n",
                 v.counters.media_segments, v.counters.media_samples, setup_.media->view.k_nearest);
    std::vector<std::string> forced_names;
    for (PassId id : forced_) forced_names.emplace_back(pass_name(id));
    extra["forced_passes"] = forced_names;
    extra["view"] = {{"secondary_rays", view_.secondary}, {"shadow_rays", view_.shadows}, {"width", u.view->settings.width}, {"height", u.view->settings.height},
                     {"primitives", u.view->scene.prim_count()}, {"shades", v.counters.shades},
                     {"exposure", u.view->exposure}, {"simulated_s", total_s - view_start_s},
                     {"media_segments", v.counters.media_segments}, {"media_samples", v.counters.media_samples}};
    if (budget_) report_budget(o, extra);
    if (image_.path.empty()) return;
    if (image_.tone_map) {
      const double exposure = apps::auto_exposure(v.image);
      apps::write_png(image_.path, apps::tone_mapped(v.image, exposure));
      fmt::print("image     {} (view pass, assembled on node 0; tone-mapped: exposure {:.4g}, extended Reinhard)\n",
                 image_.path, exposure);
      extra["image_tone_map_exposure"] = exposure;
      return;
    }
    apps::write_png(image_.path, v.image);
    fmt::print("image     {} (view pass, assembled on node 0)\n", image_.path);
  }

 private:
  // The media pass's line (the photons; the SH grid's share is charged before the view).
  void report_media(const UnifiedRender& u, bool real, nlohmann::json& extra) const {
    const double end_s = u.media_seconds();
    const PassPlan& plan = plan_.pass(PassId::media);
    if (budget_ && !budget_->choice.controls.media) {
      fmt::print("media     dropped by the error budget (below)\n");
      extra["media"] = {{"ran", false}, {"dropped_by_error_budget", true}};
      return;
    }
    if (!setup_.media || !setup_.media->photon_pass) {
      if (setup_.split.media.empty()) return;  // no medium at all: nothing to say
      fmt::print("media     photons skipped: {}{}\n", plan.reason,
                 setup_.media ? " (the view applies the media's transmittance)" : "");
      extra["media"] = {{"ran", false}, {"transmittance_applied", setup_.media != nullptr}};
      return;
    }
    const std::size_t stored = u.view && u.view->medium ? u.view->medium->photons() : 0;
    fmt::print("media     {} photons emitted (seed {}), {} stored in the media ({} surface bounces{}), {}; the pass ended at {:.6f} s {}\n",
               setup_.media->photons, setup_.media->seed, stored, u.photon_surface_events, real ? " on this rank" : "",
               setup_.media->view.radiance_estimate ? "SH grid for the radiance estimate" : "transmittance sampling",
               end_s, real ? "of wall time (this rank)" : "simulated (last node)");
    extra["media"] = {{"ran", true}, {"photons_emitted", setup_.media->photons}, {"seed", setup_.media->seed}, {"photons_stored", stored},
                      {"surface_bounces", u.photon_surface_events}, {"radiance_estimate", setup_.media->view.radiance_estimate},
                      {"simulated_end_s", end_s}};
    if (!setup_.media->walls) return;
    fmt::print("          {} photon flights from a scattering reached a wall ({} found no radiosity element): "
               "their power goes to the radiosity pass\n", u.wall_deposits + u.wall_missed, u.wall_missed);
    extra["media"]["wall_deposits"] = u.wall_deposits;
    extra["media"]["wall_missed"] = u.wall_missed;
  }

  // What the media took between surfaces and what they scattered onto the walls, of the emitted light.
  void report_radiosity_media(const UnifiedRender& u, nlohmann::json& extra) const {
    const radiosity::EnergyBalance& e = u.radiosity.energy;
    const double emitted = radiosity::channel_sum(e.emitted);
    auto share = [&](const radiosity::Rgb& x) { return emitted > 0 ? radiosity::channel_sum(x) / emitted : 0.0; };
    const double walls = mean_wall_radiosity(setup_.mesh, u.radiosity.element_radiosity);
    fmt::print("          the media took {:.1f} % of the emitted light between surfaces and scattered {:.1f} % onto the "
               "walls;\n          the surfaces absorbed {:.1f} %; the walls' mean radiosity {:.4g}\n",
               100 * share(e.in_media), 100 * share(e.injected), 100 * share(e.absorbed), walls);
    extra["mean_wall_radiosity"] = walls;
    extra["media_share"] = share(e.in_media);
    extra["scattered_onto_walls_share"] = share(e.injected);
    extra["surfaces_absorbed_share"] = share(e.absorbed);
  }

  scene::SceneDescription description_;
  Plan plan_;
  RenderSetup setup_;  // surfaces without the media's bounds, radiosity mesh, media
  std::size_t photons_ = kDefaultPhotons;
  std::uint64_t seed_ = 1;
  radiosity::ParallelOptions options_;
  ImageOutput image_;
  bool progress_;  // gcsim run: a line per loop on a terminal
  std::string scene_file_;  // as given: a file's path or a built-in scene's name
  std::vector<PassId> forced_;  // --force-pass: off in the plan, run anyway
  ViewSettings view_;
  struct Budget {
    double error;
    BudgetChoice choice;
  };
  std::optional<Budget> budget_;  // --error-budget

  // The render under the budget against the full plan on the same machine (simulated again).
  void report_budget(const RenderOutcome& o, nlohmann::json& extra) const {
    for (const std::string& r : budget_->choice.reasons) fmt::print("budget    {}\n", r);
    if (o.options.backend != "simulated") {
      fmt::print("budget    the full plan is compared on the simulated backend only\n");
      return;
    }
    RenderControls full_plan;
    full_plan.photons = photons_;
    full_plan.seed = seed_;
    const RenderRun full = render_with(description_, plan_, full_plan, o.render->view->exposure, o.options.simulation);
    const double error = relative_rmse(o.render->view->result.image, full.image), s = o.run.simulated_seconds();
    fmt::print("budget    {:.6f} s simulated against the full plan's {:.6f} s ({:.1f} % saved); relative RMSE {:.4f} "
               "against the full plan's image (budget {:g})\n",
               s, full.simulated_s, 100 * (1 - s / full.simulated_s), error, budget_->error);
    extra["error_budget"] = {{"budget", budget_->error}, {"reasons", budget_->choice.reasons}, {"full_plan_simulated_s", full.simulated_s},
                             {"simulated_s", s}, {"relative_rmse_against_full_plan", error}};
  }

  // The plan skipped radiosity as adding nothing to the view; the forced pass measures what it adds.
  void report_forced_radiosity(const UnifiedRender& u, nlohmann::json& extra) const {
    const ReflectedLight r = reflected_light(setup_.mesh, u.radiosity.element_radiosity);
    extra["forced_reflected_max"] = r.largest;
    if (r.element < 0) {
      fmt::print("          forced on: no element reflects any light (B - E = 0 on all {}), so the view, which shows\n"
                 "          the emission itself, gains nothing: the same image as without the pass\n",
                 u.radiosity.element_radiosity.size());
      return;
    }
    const std::string material = r.material >= 0 && std::size_t(r.material) < description_.materials.size()
                                     ? fmt::format("material {} ('{}')", r.material, description_.materials[std::size_t(r.material)].name)
                                     : std::string("a surface");
    fmt::print("warning   forced on: element {} of {} reflects light (largest channel of B - E {:.6g}), which the view\n"
               "          does not show: the plan's reason to skip radiosity is wrong for this scene; please report it\n",
               r.element, material, r.largest);
  }

  bool runs_forced(PassId id) const { return std::ranges::find(forced_, id) != forced_.end(); }
  bool runs(PassId id) const { return plan_.pass(id).on || runs_forced(id); }
  // --force-pass NAME: only passes whose zero contribution the view can run and add as it is.
  void force(const std::string& name) {
    for (PassId id : {PassId::radiosity, PassId::specular, PassId::shadows, PassId::media})
      if (name == pass_name(id)) {
        if (!plan_.pass(id).on) forced_.push_back(id);
        return;
      }
    if (name == "view")
      throw std::invalid_argument("--force-pass view: the view pass always runs; the passes that can be forced are "
                                  "radiosity, specular, shadows and media");
    throw std::invalid_argument(
        fmt::format("--force-pass {}: no such pass; expected radiosity, specular, shadows or media", name));
  }
};

pipeline::AppSpec spec() {
  pipeline::AppSpec s;
  s.name = "render";
  s.summary = "Render a scene (a scene file or a built-in scene) with the passes its plan needs (radiosity, the media's photons, then the ray-traced view).";
  s.examples = {"gcsim plan scenes/cornell.toml --nodes 8  which passes a scene needs, and why",
                "gcsim render scenes/cornell-mirror-glass.toml --nodes 8 --image out.png  radiosity, then the ray-traced view",
                "gcsim render scenes/cornell-fog.toml --nodes 8 --image fog.png  radiosity, photons, view through the fog"};
  s.run_footer = "Example:\n  gcsim plan scenes/cornell.toml --nodes 8\n  gcsim render scenes/cornell-mirror-glass.toml --nodes 8 --image out.png --json out.json\n"
                 "  gcsim render scenes/cornell-fog.toml --nodes 8 --photons 100000 --image fog.png\n"
                 "  (gcsim run render --scene FILE ... is the same command)";
  s.options = [](CLI::App& cmd, pipeline::Verb verb) -> pipeline::ExperimentFactory {
    auto scene = std::make_shared<std::string>();
    auto image = std::make_shared<ImageOutput>();
    auto forced = std::make_shared<std::vector<std::string>>();
    auto budget = std::make_shared<double>(0.0);
    auto photons = std::make_shared<std::size_t>(kDefaultPhotons);
    auto seed = std::make_shared<std::uint64_t>(1);
    cmd.add_option("scene", *scene, "a scene file (scenes/*.toml, .obj, .wld) or a built-in scene's name (required)");
    // `gcsim run render --scene FILE`, as tests and docs/scenes.md write it: an alias left out of the help.
    cmd.add_option("--scene", *scene, "the scene, as the positional")->group("");
    cmd.add_option("--image", image->path, "write the view pass's image (PNG, the scene's [image] size)");
    cmd.add_flag("--tone-map", image->tone_map,
                 "tone-map the PNG: an automatic exposure (the 99th percentile of the lit pixels to white) and\n"
                 "the extended Reinhard curve, as `gcsim run media` does; without it the PNG shows the radiance as\n"
                 "it is (exposed by the radiosity pass when there is one), clipped at 1");
    cmd.add_option("--force-pass", *forced,
                   "run a pass the plan has off (radiosity: the solve on every node, checked to find no reflected\n"
                   "light; specular: reflected and refracted rays; shadows: shadow rays; media: the photon pass and\n"
                   "every medium, even one with sigma_s = sigma_a = 0); what it adds is exactly nothing, so the\n"
                   "image is the same bit for bit, at its cost in time")
        ->delimiter(',');
    cmd.add_option("--error-budget", *budget,
                   "accept this relative image error (e.g. 0.02): coarsen what an estimate says costs less (radiosity\n"
                   "energy, reflection depth) and drop media too thin to matter, then render the full plan too and\n"
                   "report the time saved and the error measured against it")
        ->check(CLI::Range(1e-9, 0.999999));
    cmd.add_option("--photons", *photons,
                   "photons the media pass emits, over all nodes (more: less noise in the media's glow, a longer pass)")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t(1), std::size_t(100000000)));
    cmd.add_option("--seed", *seed,
                   "the random streams of the media: the photons each node emits and the view's distance samples.\n"
                   "The same seed gives the same image bit for bit on any node count; another seed shows the\n"
                   "photon noise. Scenes without a medium draw no random numbers")
        ->capture_default_str();
    const bool progress = verb == pipeline::Verb::run;
    return [scene, image, forced, budget, photons, seed, progress] {
      if (scene->empty())
        throw CLI::ValidationError("SCENE", "missing: give a scene file (e.g. gcsim render scenes/cornell.toml) or a built-in "
                                            "scene's name");
      return std::make_unique<RenderExperiment>(*scene, *image, *forced, *budget, *photons, *seed, progress);
    };
  };
  // `gcsim render SCENE.toml ...` is `gcsim run render --scene SCENE.toml ...`, top-level as the
  // plan's companion.
  s.commands = [](pipeline::CommandGroups& g) {
    add_plan_command(g);
    add_render_accuracy_command(g);
    add_plan_accuracy_command(g);
    pipeline::add_run_command(*g.app, spec());
  };
  return s;
}
const pipeline::AppRegistrar registrar{spec()};

}  // namespace
}  // namespace gcsim::render::app
