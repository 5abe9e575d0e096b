// Registers the participating-media renderer (Tokuyoshi and Maruyama) with the gcsim pipeline:
// `gcsim run media` and `gcsim sweep media`.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/common/image.hpp"
#include "apps/media/app/commands.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/media/parallel_media.hpp"
#include "apps/common/tone_map.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/pipeline/resource_check.hpp"

namespace gcsim::media::app {
namespace {

struct MediaFlags {
  std::string scene = "small";
  std::string estimator = "radiance";
  double b = 8.0;
  double b_histogram = 0.0;
  double alpha = MarchSettings{}.defensive_alpha;
  double max_voxel_optical_depth = MarchSettings{}.max_voxel_optical_depth;
  std::string rounding = "at-least-one";
  // Not given: the scene's. A given value is used as given or refused, never read as "default".
  std::optional<long> photons;
  std::optional<int> k;
  std::optional<int> width, height;
  unsigned long long seed = 1;
  std::string image;
  double exposure = 0.0;  // 0: auto (tone_map.hpp)
};

struct MediaOutcome : pipeline::Outcome {
  ParallelMediaResult result;
  std::vector<RenderCounters> per_node;  // one slot per processor, never sent; summed after the run
  MediaHostThreads host;                 // --host-threads
};

class MediaExperiment final : public pipeline::Experiment {
 public:
  explicit MediaExperiment(const MediaFlags& f)
      : flags_(f), scene_(load_media_scene(f.scene)), settings_{*parse_estimator(f.estimator), f.b, f.b_histogram, f.alpha, f.rounding == "at-least-one",
                                                                   f.max_voxel_optical_depth} {
    if (f.photons) scene_.photons_emitted = static_cast<std::size_t>(*f.photons);
    if (f.k) scene_.k_nearest = static_cast<std::size_t>(*f.k);
    if (f.width) scene_.image.width = *f.width;
    if (f.height) scene_.image.height = *f.height;
    scene_.seed = f.seed;
  }

  std::unique_ptr<pipeline::Outcome> new_outcome(int nodes) const override {
    auto o = std::make_unique<MediaOutcome>();
    o->result.image = apps::Image(scene_.image.width, scene_.image.height);
    o->per_node.resize(static_cast<std::size_t>(nodes));
    return o;
  }
  parix::Program program(pipeline::Outcome& out) const override {
    auto& o = pipeline::outcome_as<MediaOutcome>(out);
    // --host-threads: tiles rendered ahead on the host (simulated backend; under MPI each rank renders its own).
    o.host.workers = o.options.backend == "simulated" ? o.options.host_threads - 1 : 0;
    return [this, &o](parix::Processor& p) { media_program(p, scene_, settings_, flags_.seed, o.result, o.per_node, &o.host); };
  }
  void after_run(pipeline::Outcome& out) const override {
    auto& o = pipeline::outcome_as<MediaOutcome>(out);
    for (const RenderCounters& c : o.per_node) o.result.counters.add(c);
  }
  // Every node holds the all-gathered photon maps; node 0 the image; a segment draws b samples per
  // unit of S. Checked before anything is allocated (resource_check.hpp).
  std::vector<pipeline::MemoryNeed> node_memory(int, int* processor) const override {
    *processor = 0;
    const std::int64_t pixels = pipeline::saturating_product(scene_.image.width, scene_.image.height);
    const double samples = std::max(flags_.b, flags_.b_histogram) * double(sizeof(double));
    return {{"photon maps", pipeline::saturating_product(std::int64_t(scene_.photons_emitted), sizeof(Photon))},
            {"image", pipeline::saturating_product(pixels, sizeof(glm::vec3))},
            {"march samples of a segment with S = 1 (--b)", samples >= 9e18 ? INT64_MAX : std::int64_t(samples)}};
  }
  std::int64_t host_memory(int nodes) const override {
    std::int64_t bytes = 0;
    int processor = 0;
    for (const pipeline::MemoryNeed& n : node_memory(nodes, &processor))
      bytes = n.bytes > INT64_MAX - bytes ? INT64_MAX : bytes + n.bytes;
    return pipeline::saturating_product(bytes, std::max(1, nodes));
  }
  void print_setup(int nodes) const override { fmt::print("media     {}, {} nodes\n", setup_line(), nodes); }
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override;
  void print_sweep_setup() const override { fmt::print("media     {}\n", setup_line()); }
  pipeline::RunInputs run_inputs() const override {
    pipeline::RunInputs in;
    in.scene = flags_.scene, in.seeds = {{"seed", flags_.seed}};
    if (!flags_.image.empty()) in.outputs.push_back(flags_.image);
    return in;
  }

 private:
  std::string setup_line() const {
    return fmt::format("scene {}, {}x{}, {} photons emitted, k = {}, estimator {}, b = {}", scene_.name, scene_.image.width,
                       scene_.image.height, scene_.photons_emitted, scene_.k_nearest, flags_.estimator, flags_.b);
  }
  MediaFlags flags_;
  MediaScene scene_;
  MarchSettings settings_;
};

void MediaExperiment::report(const pipeline::Outcome& out, nlohmann::json& extra) const {
  const ParallelMediaResult& r = pipeline::outcome_as<MediaOutcome>(out).result;
  fmt::print("photons   {} stored outside, {} inside; grids {}x{}x{} and {}x{}x{} voxels\n", r.outside_photons,
             r.inside_photons, r.outside_dims.x, r.outside_dims.y, r.outside_dims.z, r.inside_dims.x, r.inside_dims.y,
             r.inside_dims.z);
  fmt::print("messages  photon maps {} B per node after all-gather ({} B from node 0), SH grids {} B per node\n",
             r.photon_bytes_all, r.photon_bytes, r.grid_bytes_all);
  fmt::print("work      {} march samples, {} SH evaluations, {} segments\n", r.counters.march.samples,
             r.counters.march.sh_evals, r.counters.march.segments);
  if (r.counters.boundary.any())
    fmt::print("mesh      {} tree nodes and {} triangles tested by the camera paths (media_bvh_node, media_triangle_test)\n",
               r.counters.boundary.node_tests, r.counters.boundary.triangle_tests);
  fmt::print("tiles     {} tiles of {}x{} handed out dynamically: {} assignments, {} B of tile records to node 0\n",
             r.tiles, kTileSize, kTileSize, r.tile_messages, r.tile_result_bytes);
  const double grid_s = r.counters.grid_seconds, render_s = r.counters.tile_seconds;
  fmt::print("compute   SH grids {:.3f} s, tiles {:.3f} s, summed over the nodes: the grids are {:.1f} % of the render\n",
             grid_s, render_s, render_s > 0.0 ? 100.0 * grid_s / render_s : 0.0);
  if (!flags_.image.empty()) {
    const double exposure = flags_.exposure > 0.0 ? flags_.exposure : apps::auto_exposure(r.image);
    apps::write_png(flags_.image, apps::tone_mapped(r.image, exposure), 1.0f);
    fmt::print("image     {} (exposure {:.4g}{}, extended Reinhard, white {})\n", flags_.image, exposure,
               flags_.exposure > 0.0 ? "" : ": the 99th percentile of the lit pixels at white", apps::ToneMap{}.white);
  }
  extra["media"] = {{"scene", scene_.name},
                    {"estimator", flags_.estimator},
                    {"march_samples", r.counters.march.samples},
                    {"sh_evals", r.counters.march.sh_evals},
                    {"segments", r.counters.march.segments},
                    {"surface_events", r.counters.surface_events},
                    {"grid_compute_s", r.counters.grid_seconds},
                    {"tile_compute_s", r.counters.tile_seconds},
                    {"photons_outside", r.outside_photons},
                    {"photons_inside", r.inside_photons},
                    {"photon_map_bytes", r.photon_bytes_all},
                    {"sh_grid_bytes", r.grid_bytes_all}};
  if (r.counters.boundary.any()) {  // a mesh object; the sphere scenes' records stay as they were
    extra["media"]["mesh_node_tests"] = r.counters.boundary.node_tests;
    extra["media"]["mesh_triangle_tests"] = r.counters.boundary.triangle_tests;
  }
}

pipeline::ExperimentFactory declare_options(CLI::App& cmd, pipeline::Verb verb) {
  auto f = std::make_shared<MediaFlags>();
  cmd.add_option("--scene", f->scene,
                 "a built-in scene: small, exp1 (sigma_s read as albedo), exp1-literal, exp2, fog, exp1-bunny, exp2-bunny "
                 "(the Stanford bunny of scenes/meshes/bunny.obj in place of the sphere); or a scene file with a box of "
                 "fog, e.g. scenes/media-small.toml (any scene of the catalogue: one without a medium is refused, saying why)")
      ->capture_default_str();
  cmd.add_option("--estimator", f->estimator, "uniform, transmittance, radiance, equiangular, mis or grid")
      ->check(CLI::IsMember({"uniform", "transmittance", "radiance", "equiangular", "mis", "grid"}))
      ->capture_default_str();
  cmd.add_option("--b", f->b, "samples per unit of the segment integral S (M = b S, eq. 21)")
      ->check(pipeline::positive_number())
      ->capture_default_str();
  cmd.add_option("--b-histogram", f->b_histogram, "radiance estimator: M = b_h S_h (eq. 22) when > 0")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--alpha", f->alpha, "transmittance share of the defensive radiance density (0: the paper's pure density, biased where h <= 0)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd.add_option("--max-voxel-optical-depth", f->max_voxel_optical_depth,
                 "radiance estimator: draw from the transmittance where the grid's voxels are thicker than this many mean "
                 "free paths (1e9: the paper's density everywhere)")
      ->check(pipeline::positive_number())
      ->capture_default_str();
  cmd.add_option("--rounding", f->rounding,
                 "M < 1: one sample (at-least-one, notes A12) or one with probability M and weight 1/M (stochastic)")
      ->check(CLI::IsMember({"at-least-one", "stochastic"}))
      ->capture_default_str();
  cmd.add_option("--photons", f->photons, "photons emitted (default: the scene's)")->check(CLI::PositiveNumber);
  cmd.add_option("--k", f->k, "nearest photons per estimate (default: the scene's)")->check(CLI::PositiveNumber);
  cmd.add_option("--width", f->width, "image width (default: the scene's)")->check(CLI::Range(1, 16384));
  cmd.add_option("--height", f->height, "image height (default: the scene's)")->check(CLI::Range(1, 16384));
  cmd.add_option("--seed", f->seed, "random seed of photons and pixels")->capture_default_str();
  if (verb == pipeline::Verb::run) {
    cmd.add_option("--image", f->image, "Write the image as PNG");
    cmd.add_option("--exposure", f->exposure, "PNG exposure (default: the 99th percentile of the lit pixels maps to white)")
        ->check(pipeline::positive_number());
  }
  return [f] { return std::make_unique<MediaExperiment>(*f); };
}

pipeline::AppSpec media_app() {
  pipeline::AppSpec s;
  s.name = "media";
  s.summary =
      "Participating media with a photon map and SH radiance-importance sampling (Tokuyoshi and Maruyama)\n"
      "on the simulated GC: photons traced in parallel, photon maps and SH grids all-gathered, image rows\n"
      "handed out dynamically by node 0. The image does not depend on the node count.";
  s.run_footer = "\nExample:\n  gcsim run media --scene small --estimator radiance --nodes 16 --image m.png --json m.json";
  s.examples = {"gcsim run media --scene small --image m.png  participating media by photon maps, 16 nodes"};
  s.default_nodes = 16;
  s.options = declare_options;
  s.commands = [](pipeline::CommandGroups& g) { add_accuracy_command(g); };
  return s;
}

const pipeline::AppRegistrar registrar{media_app()};

}  // namespace
}  // namespace gcsim::media::app
