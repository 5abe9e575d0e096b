// gcsim plan SCENE.toml [--nodes N] [--config F] [--model M] [--json F]: the passes a scene needs, each on or
// off with the reason, and an estimate of its simulated time and memory per node.
#include <algorithm>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/resource_check.hpp"
#include "apps/raytrace/raytrace.hpp"
#include "apps/render/app/render_commands.hpp"
#include "apps/render/plan_report.hpp"
#include "apps/render/media_sample.hpp"
#include "apps/render/radiosity_sample.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/view_sample.hpp"

namespace gcsim::render::app {

namespace {
struct PlanFlags {
  std::string scene;
  pipeline::MachineOptions machine;
  // 8 loops predict every built-in scene's radiosity within 6 % (16: within 6 % too, at 1.6 times
  // the host time on CORNELL-MIRROR-GLASS; apps/render/README.md).
  int sample_loops = 8;
  int sample_photons = 8;
  int sample_tiles = -1;  // -1: chosen (sample_tile_stride); 0: count operations
  int sample_rows = 0;  // the marching's pixel rows: one in this many of each sampled tile; 0: chosen (march_row_stride)
  std::size_t photons = kDefaultPhotons;
};

// The media pass measured by media_sample.hpp, into the model; the operation count stays where the
// render would refuse the scene (said on stderr).
void measure_media(const PlanFlags& f, const scene::SceneDescription& d, const Plan& plan, int nodes, CostModel& model,
                   MediaSample& s) {
  MediaSampleOptions o;
  o.photons = f.photons;
  // At least 256 photons a node in the larger sample: with fewer (64 nodes, 1/8 of 50000) the pass's
  // time grows faster than linearly towards every photon (CORNELL-FOG 1.22 s predicted against 1.58 s).
  const std::size_t per_node_floor = 256 * std::size_t(std::max(nodes, 1));
  o.photon_divisor = int(std::clamp<std::size_t>(f.photons / per_node_floor, 1, std::size_t(f.sample_photons)));
  o.tile_stride = std::max(f.sample_tiles, 0);  // the view's sample, when given
  o.row_stride = f.sample_rows;
  try {
    s = sample_media(d, plan, f.scene, pipeline::simulation_options(f.machine, nodes), o);
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "media not sampled ({}): operation count instead\n", e.what());
    return;
  }
  model.media_seconds = s.seconds();
  model.media_bytes = s.map_bytes;
  model.media_photon_seconds = s.photon_seconds, model.media_grid_seconds = s.grid_seconds;
  model.media_march_seconds = s.march_seconds;
  // The photons' and the marching's sampled fractions, each part's share of the row.
  const double photons_u = sampled_fraction_uncertainty(double(s.traced) / double(std::max<std::size_t>(f.photons, 1)));
  const double march_u =
      sampled_fraction_uncertainty(double(s.tiles_rendered) / std::max(s.tiles, 1) / double(std::max(s.row_stride, 1)));
  model.media_uncertainty = s.seconds() > 0 ? (photons_u * s.photon_seconds + march_u * (s.grid_seconds + s.march_seconds)) / s.seconds() : 0;
  // One run of every photon when the sample is all of them (--sample-photons 1, or few photons a node).
  const bool all_photons = s.traced >= f.photons;
  const std::string photons_run = all_photons ? fmt::format("all {} photons traced once", f.photons)
                                              : fmt::format("{} and {} of the {} photons traced", s.traced / 2, s.traced, f.photons);
  const std::string photons_how = all_photons ? "as traced" : "linear in the photons through the two";
  const std::string rows = s.row_stride > 1 ? fmt::format(", one pixel row in {} of each", s.row_stride) : "";
  model.media_measured = fmt::format(
      "{}, then one run of {} tiles in {} of the view ({} of\n"
      "          {}{}) with and without the media, on the simulated machine:\n"
      "          photons ~{:.3g} s ({}),\n"
      "          SH grid ~{:.3g} s (its counts scaled to every photon), marching ~{:.3g} s (the\n"
      "          difference, the nodes' mean work scaled to every tile); the view with them ~{:.3g} s.",
      photons_run, raytrace::kRunTiles, s.tile_stride, s.tiles_rendered, s.tiles, rows, s.photon_seconds, photons_how,
      s.grid_seconds, s.march_seconds, s.view_seconds);
}

// The view, specular and shadows passes measured by view_sample.hpp, into the model; the operation
// count stays where the render would refuse the scene (said on stderr).
void measure_view(const PlanFlags& f, const scene::SceneDescription& d, const Plan& plan, int nodes, CostModel& model) {
  ViewSample s;
  try {
    s = sample_view(d, plan, f.scene, pipeline::simulation_options(f.machine, nodes), {.tile_stride = std::max(f.sample_tiles, 0)});
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "view not sampled ({}): operation count instead\n", e.what());
    return;
  }
  model.view_sampled = true;
  model.view_seconds = s.view_seconds, model.specular_seconds = s.specular_seconds, model.shadow_seconds = s.shadow_seconds;
  model.view_bytes = s.bytes_per_node;
  model.view_uncertainty = sampled_fraction_uncertainty(double(s.tiles_rendered) / std::max(s.tiles, 1));
  std::string rows = "view";
  if (plan.pass(PassId::specular).on) rows += ", specular";
  if (plan.pass(PassId::shadows).on) rows += ", shadows";
  model.view_measured = fmt::format(
      "{}: one run of {} tiles in {} of the view ({} of {}) traced on the simulated\n"
      "          machine{}, {} run{} adding one kind of ray at a time (the difference is the pass's); the\n"
      "          nodes' mean work scaled to every tile, their waiting kept; {:.2g} s of host time.",
      rows, raytrace::kRunTiles, s.tile_stride, s.tiles_rendered, s.tiles, plan.pass(PassId::media).on ? " without the media" : "", s.runs,
      s.runs > 1 ? "s" : "", s.host_seconds);
}

}  // namespace

void add_plan_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<PlanFlags>();
  CLI::App* cmd = g.app->add_subcommand(
      "plan",
      "Decide from a scene file alone which passes a render needs (view, radiosity, specular ray tracing,\n"
      "media, shadows), say why each is on or off, and estimate each pass's simulated time and memory per\n"
      "node on the chosen machine before anything runs.");
  cmd->add_option("scene", f->scene, "a scene file (scenes/*.toml, .obj, .wld; apps/common/scene/README.md) or a built-in scene's name")->required();
  // Declared as every command declares them, so a bad --model or --nodes is a usage error before
  // the scene is read or any sample runs.
  pipeline::add_nodes_option(cmd, f->machine.nodes, "1");
  pipeline::add_config_option(cmd, f->machine.config);
  pipeline::add_json_option(cmd, f->machine.json, "the plan");
  pipeline::add_model_option(cmd, f->machine.model, "Network model of the samples run on the simulated machine");
  cmd->add_option("--sample-loops", f->sample_loops,
                  "radiosity loops run on the simulated machine to measure a loop's time (communication\n"
                  "included); 0: count operations only, as for the other passes")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--sample-photons", f->sample_photons,
                  "D: the media pass is measured on the simulated machine by tracing 1/D and 1/(2D) of the\n"
                  "photons (the time taken as linear in them) and rendering the view's sample (--sample-tiles)\n"
                  "with and without the media; 1: every photon; 0: count operations instead (CORNELL-FOG,\n"
                  "8 nodes: 12.8 s counted against 7.1 s simulated)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--sample-tiles", f->sample_tiles,
                  "K: the view (with specular and shadow rays when those passes are on) is measured on the\n"
                  "simulated machine by tracing one run of 4 tiles in K, on diagonals, and scaling up;\n"
                  "default: K chosen (up to 4, at least 16 tiles a node); 1: every tile (exact); 0: count\n"
                  "operations instead. The media's marching is measured on the same tiles (K chosen when 0)")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--sample-rows", f->sample_rows,
                  "R: the media's marching on the sampled tiles traces one pixel row in R of each tile and\n"
                  "scales its work to the tile (most of a plan's host time is that marching); default: R\n"
                  "chosen for one run of tiles in K: 4 / K rows, a quarter of the pixels; where a node has 4\n"
                  "tiles or more, 8 / K, an eighth, where one row in 8 of the sampled tiles is 4096 pixels or\n"
                  "more, and 16 / K, a sixteenth, where that is 16384 pixels or more; at least 1 (every row)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--photons", f->photons, "photons the render will emit (gcsim render --photons)")
      ->capture_default_str()
      ->check(pipeline::positive_number())
      ->check(CLI::Range(1.0, 2147483647.0));  // the cost model counts them in an int
  cmd->callback([f] {
    pipeline::check_writable(f->machine.json, "--json");  // before the samples' runs
    const scene::SceneDescription d = scene::load_scene(f->scene);
    const parix::SimulationOptions simulation = pipeline::simulation_options(f->machine, 1);
    const machine::MachineConfig& machine = simulation.config;
    const int nodes = f->machine.nodes > 0 ? f->machine.nodes : 1;
    // The samples render the scene's image on node 0, which holds it as the render does (8-bit RGB);
    // the host holds it in floats. An [image] too large for either fails here, at once.
    const std::int64_t node_image_bytes = raytrace::assembled_image_bytes(d.image.width, d.image.height);
    pipeline::check_node_memory({{"image", node_image_bytes}}, 0, machine.memory_bytes, simulation.memory_limit);
    const std::int64_t host_image_bytes =
        pipeline::saturating_product(pipeline::saturating_product(d.image.width, d.image.height), sizeof(glm::vec3));
    pipeline::check_host_memory(host_image_bytes, fmt::format("the {}x{} image of {}", d.image.width, d.image.height, f->scene));
    const Plan plan = make_plan(d);
    CostModel model;
    model.photons = int(f->photons);
    MediaSample media;  // first, as the render: radiosity starts from what the photons leave on the walls
    if (plan.pass(PassId::media).on && f->sample_photons > 0) measure_media(*f, d, plan, nodes, model, media);
    if (plan.pass(PassId::radiosity).on && f->sample_loops > 0) {
      model.radiosity_deposits = !media.wall_power.empty();
      const RadiositySample s = sample_radiosity_loops(d, f->scene, pipeline::simulation_options(f->machine, nodes),
                                                       f->sample_loops, &media.wall_power);
      model.radiosity_seconds_per_loop = s.seconds_per_loop;
      model.radiosity_loops = s.expected_loops;
      model.radiosity_uncertainty = s.relative_uncertainty;
      model.radiosity_peak_bytes = s.peak_bytes;
    }
    if (f->sample_tiles != 0) measure_view(*f, d, plan, nodes, model);
    fmt::print("{}", format_plan(plan, machine, nodes, model));
    if (!f->machine.json.empty()) pipeline::write_json_file(f->machine.json, plan_json(plan, machine, nodes, model));
  });
}

}  // namespace gcsim::render::app
