#include "apps/raytrace/app/render_options.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/raytrace/algorithm.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/pipeline/option_checks.hpp"

namespace gcsim::raytrace::app {

namespace {

const std::string kScenesHelp =
    "Scene: spheres-a, spheres-b (512 spheres on an 8x8x8 grid, two radii: the paper's photos 1, 2), "
    "spheres-random (photo 3), teapot (552 triangles, photo 4), teapots (4416, photo 5), whitted (mirror and "
    "glass spheres: secondary rays), another application's built-in scene it can lower, or a scene file: "
    ".toml (point and spot lights), .obj, .wld (the thesis's WORLD files)";
const std::string kAlgoHelp =
    "Primary-ray algorithm: A1 (BVH only), A2 (BVH + front-to-back child sorting and pruning), A2p = A2' "
    "(per-subregion dynamic subtree), A3 (subtree + sorting), A4 (A3 + subregion uniformity test), "
    "B1 (Arvo-Kirk ray classification)";

}  // namespace

void add_render_options(CLI::App* cmd, RenderOptions& o, bool shading_options) {
  cmd->add_option("--scene", o.scene, kScenesHelp)->capture_default_str();
  cmd->add_option("--algo", o.algo, kAlgoHelp)
      ->check(CLI::IsMember({"A1", "A2", "A2p", "A2'", "A3", "A4", "B1"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_option("--tile", o.tile, "Subregion size m (m x m pixels): the unit of subtrees, uniformity tests and distribution (paper: 4, 8, 16, 32)")
      ->check(CLI::Range(2, 1024))
      ->capture_default_str();
  cmd->add_option("--size", o.size, "Image width and height in pixels (the paper: 512)")->check(CLI::Range(8, 8192))->capture_default_str();
  if (!shading_options) return;
  cmd->add_option("--shading", o.shading,
                  "local: primary rays only (Lambert/Phong, no shadows); whitted: shadow rays, reflection and refraction; "
                  "auto: whitted when the scene has mirrors or glass")
      ->check(CLI::IsMember({"auto", "local", "whitted"}))
      ->capture_default_str();
  cmd->add_flag("--no-pencils", o.no_pencils, "Trace secondary rays in the whole tree instead of the pencil subtrees of section 2.3");
  cmd->add_option("--max-depth", o.max_depth, "Reflection/refraction levels (whitted)")->check(CLI::Range(0, 32))->capture_default_str();
}

RenderSettings settings_of(const RenderOptions& o, const Scene& scene) {
  RenderSettings s;
  s.algorithm = *parse_algorithm(o.algo);
  s.tile = o.tile;
  s.width = s.height = o.size;
  s.shading = o.shading == "whitted" || (o.shading == "auto" && scene.has_secondary_effects()) ? Shading::whitted : Shading::local;
  s.pencils = !o.no_pencils;
  s.max_depth = o.max_depth;
  return s;
}

Scene load_scene_or_fail(const std::string& name) {
  pipeline::check_scene_file(name, scene::builtin_scene_names());
  try {
    return load_scene(name);  // a loader's SceneError names the file and line and ends with the file exit code
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--scene", e.what());
  }
}

void print_scene(const Scene& s, const Bvh& bvh) {
  fmt::print("scene     {}: {} spheres, {} triangles; BVH of {} boxes by clustering, depth {}\n", s.name, s.spheres.size(),
             s.triangles.size(), bvh.nodes.size(), bvh.depth());
}

nlohmann::json counters_json(const TraceCounters& c) {
  const double rays = std::max<double>(1, double(c.primary_rays));
  return {{"primary_rays", c.primary_rays},
          {"bv_tests_per_ray", c.primary_box_tests / rays},
          {"prim_tests_per_ray", c.primary_prim_tests / rays},
          {"primary_bv_tests", c.primary_box_tests},
          {"primary_prim_tests", c.primary_prim_tests},
          {"total_tests", c.box_tests() + c.prim_tests()},
          {"secondary_rays", c.secondary_rays},
          {"secondary_in_pencil", c.secondary_in_pencil},
          {"first_bounce_rays", c.first_bounce_rays},
          {"first_bounce_in_pencil_tiles", c.first_bounce_in_pencil_tiles},
          {"first_bounce_bv_tests", c.first_bounce_box_tests},
          {"first_bounce_prim_tests", c.first_bounce_prim_tests},
          {"shadow_rays", c.shadow_rays},
          {"secondary_bv_tests", c.secondary_box_tests},
          {"secondary_prim_tests", c.secondary_prim_tests},
          {"plane_tests", c.plane_tests},
          {"subtree_nodes", c.subtree_nodes},
          {"pencils", c.pencils},
          {"child_sorts", c.child_sorts},
          {"uniformity_tests", c.uniformity_tests},
          {"uniform_regions", c.uniform_regions},
          {"uniform_pixels", c.uniform_pixels},
          {"uniformity_box_checks", c.uniformity_box_checks},
          {"beams", c.beams},
          {"shades", c.shades}};
}

void print_counters(const TraceCounters& c) {
  const double rays = std::max<double>(1, double(c.primary_rays));
  fmt::print("primary   {} rays: BV tests/ray {:.2f}, primitive tests/ray {:.2f}, total {:.0f}k tests\n", c.primary_rays,
             c.primary_box_tests / rays, c.primary_prim_tests / rays, (c.primary_box_tests + c.primary_prim_tests) / 1e3);
  if (c.plane_tests > 0)
    fmt::print("subtrees  {} box-plane classifications, {} nodes written\n", c.plane_tests, c.subtree_nodes);
  if (c.uniformity_tests > 0)
    fmt::print("uniform   {} of {} regions uniform, {} pixels filled without traversal ({} box checks)\n", c.uniform_regions,
               c.uniformity_tests, c.uniform_pixels, c.uniformity_box_checks);
  if (c.beams > 0) fmt::print("beams     {} ray-classification beams\n", c.beams);
  if (c.secondary_rays + c.shadow_rays > 0) {
    fmt::print("secondary {} reflected/refracted rays ({} through {} pencil subtrees), {} shadow rays; "
               "{} BV + {} primitive tests\n",
               c.secondary_rays, c.secondary_in_pencil, c.pencils, c.shadow_rays, c.secondary_box_tests, c.secondary_prim_tests);
    if (c.first_bounce_rays > 0)
      fmt::print("1st bounce {} rays, {} in subregions with a pencil, {} inside it; BV tests/ray {:.2f}, primitive tests/ray {:.2f}\n",
                 c.first_bounce_rays, c.first_bounce_in_pencil_tiles, c.secondary_in_pencil,
                 double(c.first_bounce_box_tests) / c.first_bounce_rays, double(c.first_bounce_prim_tests) / c.first_bounce_rays);
  }
}

}  // namespace gcsim::raytrace::app
