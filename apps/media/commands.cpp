// `gcsim run media`: the participating-media renderer on the simulated GC (issue 9).
// Written in the style of apps/cli/raytrace_commands.cpp; the lead moves it onto the app registry.
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli/commands.hpp"
#include "apps/common/image.hpp"
#include "apps/media/parallel_media.hpp"

namespace gcsim::cli {
namespace {

using namespace gcsim::media;

struct MediaRunOptions {
  std::string scene = "small";
  std::string estimator = "radiance";
  double b = 8.0;
  double b_histogram = 0.0;
  double alpha = 0.1;
  long photons = 0;  // 0: the scene's
  int k = 0;         // 0: the scene's
  int width = 0, height = 0;
  unsigned long long seed = 1;
  std::string image;
  float exposure = 1.0f;
  MachineOptions machine;
};

nlohmann::json counters_json(const ParallelMediaResult& r) {
  return {{"march_samples", r.counters.march.samples}, {"sh_evals", r.counters.march.sh_evals},
          {"segments", r.counters.march.segments},     {"surface_events", r.counters.surface_events},
          {"photons_outside", r.outside_photons},      {"photons_inside", r.inside_photons},
          {"photon_map_bytes", r.photon_bytes_all},    {"sh_grid_bytes", r.grid_bytes_all}};
}

}  // namespace

void add_media_commands(CommandGroups& g) {
  auto o = std::make_shared<MediaRunOptions>();
  CLI::App* cmd = g.run->add_subcommand(
      "media", "Participating media with a photon map and SH radiance-importance sampling (Tokuyoshi and Maruyama)");
  cmd->add_option("--scene", o->scene, "small, exp1 (sigma_s read as albedo), exp1-literal, exp2")->capture_default_str();
  cmd->add_option("--estimator", o->estimator, "uniform, transmittance, radiance, equiangular, mis or grid")
      ->check(CLI::IsMember({"uniform", "transmittance", "radiance", "equiangular", "mis", "grid"}))
      ->capture_default_str();
  cmd->add_option("--b", o->b, "samples per unit of the segment integral S (M = b S, eq. 21)")->capture_default_str();
  cmd->add_option("--b-histogram", o->b_histogram, "radiance estimator: M = b_h S_h (eq. 22) when > 0");
  cmd->add_option("--alpha", o->alpha, "transmittance share of the defensive radiance density")->capture_default_str();
  cmd->add_option("--photons", o->photons, "photons emitted (default: the scene's)");
  cmd->add_option("--k", o->k, "nearest photons per estimate (default: the scene's)");
  cmd->add_option("--width", o->width, "image width (default: the scene's)");
  cmd->add_option("--height", o->height, "image height (default: the scene's)");
  cmd->add_option("--seed", o->seed, "random seed of photons and pixels")->capture_default_str();
  cmd->add_option("--image", o->image, "Write the image as PNG");
  cmd->add_option("--exposure", o->exposure, "PNG exposure")->capture_default_str();
  add_machine_options(cmd, o->machine);
  cmd->footer("\nExample:\n  gcsim run media --scene small --estimator radiance --nodes 16 --image m.png --json m.json");
  cmd->callback([o] {
    MediaScene scene = scene_by_name(o->scene);
    if (o->photons > 0) scene.photons_emitted = static_cast<std::size_t>(o->photons);
    if (o->k > 0) scene.k_nearest = static_cast<std::size_t>(o->k);
    if (o->width > 0) scene.camera.width = o->width;
    if (o->height > 0) scene.camera.height = o->height;
    scene.seed = o->seed;
    MarchSettings settings{*parse_estimator(o->estimator), o->b, o->b_histogram, o->alpha};
    const parix::SimulationOptions sim = simulation_options(o->machine, 16);
    fmt::print("media     scene {}, {}x{}, {} photons emitted, k = {}, estimator {}, b = {}, {} nodes\n", scene.name,
               scene.camera.width, scene.camera.height, scene.photons_emitted, scene.k_nearest, o->estimator, o->b,
               sim.nodes);
    const ParallelMediaResult r = render_media_parallel(scene, settings, o->seed, sim);
    fmt::print("photons   {} stored outside, {} inside; grids {}x{}x{} and {}x{}x{} voxels\n", r.outside_photons,
               r.inside_photons, r.outside_dims.x, r.outside_dims.y, r.outside_dims.z, r.inside_dims.x,
               r.inside_dims.y, r.inside_dims.z);
    fmt::print("messages  photon maps {} B per node after all-gather ({} B from node 0), SH grids {} B per node\n",
               r.photon_bytes_all, r.photon_bytes, r.grid_bytes_all);
    fmt::print("work      {} march samples, {} SH evaluations, {} segments\n", r.counters.march.samples,
               r.counters.march.sh_evals, r.counters.march.segments);
    if (!o->image.empty()) {
      apps::write_png(o->image, r.image, o->exposure);
      fmt::print("image     {}\n", o->image);
    }
    nlohmann::json extra;
    extra["media"] = counters_json(r);
    extra["media"]["scene"] = scene.name;
    extra["media"]["estimator"] = o->estimator;
    report_run(r.run, o->machine, extra);
  });
}

}  // namespace gcsim::cli
