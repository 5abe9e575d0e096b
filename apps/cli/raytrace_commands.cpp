// gcsim run|table|sweep|bench raytrace: the ray tracer of Naruse, Shinya and Saito (dynamic
// subtrees) on the simulated GC-PowerPlus, its paper tables, node sweeps and host speed.
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli/commands.hpp"
#include "apps/cli/run_support.hpp"
#include "apps/common/image.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/cost_model.hpp"
#include "apps/raytrace/embree_reference.hpp"
#include "apps/raytrace/obj_loader.hpp"
#include "apps/raytrace/paper_figures.hpp"
#include "apps/raytrace/parallel_render.hpp"
#include "apps/raytrace/primary_tracer.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::cli {
namespace {

using namespace gcsim::raytrace;

struct RenderOptions {
  std::string scene = "teapots";
  std::string algo = "A4";
  int tile = 8;
  int size = 512;
  std::string shading = "auto";
  bool no_pencils = false;
  int max_depth = 5;
};

const std::string kScenesHelp =
    "Scene: spheres-a, spheres-b (512 spheres on an 8x8x8 grid, two radii: the paper's photos 1, 2), "
    "spheres-random (photo 3), teapot (552 triangles, photo 4), teapots (4416, photo 5), whitted (mirror and "
    "glass spheres: secondary rays), or a .obj file";
const std::string kAlgoHelp =
    "Primary-ray algorithm: A1 (BVH only), A2 (BVH + front-to-back child sorting and pruning), A2p = A2' "
    "(per-subregion dynamic subtree), A3 (subtree + sorting), A4 (A3 + subregion uniformity test), "
    "B1 (Arvo-Kirk ray classification)";

void add_render_options(CLI::App* cmd, RenderOptions& o, bool shading_options = true) {
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
  try {
    return load_scene(name);
  } catch (const ObjError& e) {
    throw CLI::ValidationError("--scene", e.what());
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

// ---------------------------------------------------------------- run
void add_run(CommandGroups& g) {
  struct Opts {
    RenderOptions render;
    MachineOptions machine;
    std::string distribute = "dynamic";
    std::string image;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = g.run->add_subcommand(
      "raytrace",
      "Ray trace a scene on the simulated GC: the image is cut into subregions (tiles), the tiles are\n"
      "distributed over the nodes, each node traces its tiles with the chosen algorithm and charges the\n"
      "counted ray-box and ray-primitive tests to its CPU, and node 0 assembles the image.\n"
      "Prints the paper's counters (BV and primitive tests per ray) and simulated next to wall time.");
  add_render_options(cmd, o->render);
  add_machine_options(cmd, o->machine);
  cmd->add_option("--distribute", o->distribute,
                  "static: contiguous blocks of tiles per node; interleaved: tile i to node i mod N; "
                  "dynamic: node 0 hands out tiles on request (load balancing)")
      ->check(CLI::IsMember({"static", "interleaved", "dynamic"}))
      ->capture_default_str();
  cmd->add_option("--image", o->image, "Write the image as PNG");
  cmd->footer("\nExample:\n  gcsim run raytrace --scene teapots --algo A4 --nodes 16 --image t.png --json t.json");
  cmd->callback([o] {
    const Scene scene = load_scene_or_fail(o->render.scene);
    const Bvh bvh = build_bvh_by_clustering(scene);
    const RenderSettings settings = settings_of(o->render, scene);
    const parix::SimulationOptions sim = simulation_options(o->machine, 16);
    const Distribution d = *parse_distribution(o->distribute);
    print_scene(scene, bvh);
    fmt::print("render    {}x{}, {} ({}), {}x{} subregions, {} shading, {} distribution over {} nodes\n", settings.width,
               settings.height, paper_name_of(settings.algorithm), description_of(settings.algorithm), settings.tile,
               settings.tile, settings.shading == Shading::whitted ? "Whitted" : "local", name_of(d), sim.nodes);
    const ParallelRender r = render_parallel(scene, bvh, settings, d, sim);
    print_counters(r.counters);
    int lo = 1 << 30, hi = 0;
    for (int t : r.tiles_per_node) lo = std::min(lo, t), hi = std::max(hi, t);
    fmt::print("tiles     {} in all, {}..{} per node\n", Tiling{settings.width, settings.height, settings.tile}.count(), lo, hi);
    if (!o->image.empty()) {
      apps::write_png(o->image, r.image);
      fmt::print("image     {}\n", o->image);
    }
    nlohmann::json extra;
    extra["raytrace"] = counters_json(r.counters);
    extra["raytrace"]["scene"] = scene.name;
    extra["raytrace"]["algorithm"] = std::string(paper_name_of(settings.algorithm));
    extra["raytrace"]["tile"] = settings.tile;
    extra["raytrace"]["size"] = settings.width;
    extra["raytrace"]["distribution"] = std::string(name_of(d));
    extra["raytrace"]["tiles_per_node"] = r.tiles_per_node;
    report_run(r.run, o->machine, extra);
  });
}

// ---------------------------------------------------------------- table
struct Measured {
  TraceCounters counters;
  double simulated = 0;  // seconds on one CPU of the machine
  double wall = 0;
};

Measured measure(const Scene& scene, const Bvh& bvh, Algorithm a, int tile, int size, const machine::MachineConfig& config) {
  RenderSettings rs;
  rs.algorithm = a;
  rs.tile = tile;
  rs.width = rs.height = size;
  rs.shading = Shading::local;
  const RenderOutput out = render_image(scene, bvh, rs);
  return {out.counters, machine::to_seconds(single_cpu_time(out.counters, config)), out.wall_seconds};
}

std::string paper_value(double v, int decimals) { return v < 0 ? "-" : fmt::format("{:.{}f}", v, decimals); }
std::string min_sec(double s) { return fmt::format("{}'{:02d}\"", int(s) / 60, int(std::lround(s)) % 60); }

void add_table(CommandGroups& g) {
  struct Opts {
    int size = 512;
    int tile = 8;
    std::string which = "both";
    std::string csv = "raytrace_table";
    std::string config;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = g.table->add_subcommand(
      "raytrace",
      "The paper's table 1 (6 algorithms x 5 scenes: time, BV and primitive tests per ray, total tests) and\n"
      "table 2 (A4 time against subregion size), ours beside the paper's. Our time is the simulated time of\n"
      "one GC-PowerPlus CPU (PowerPC 601) from the counted operations; the paper's is a sun4/260's. Counts\n"
      "are exact. Expect the paper's ordering: A1 the most tests, A2' far fewer than A1, A4 the fewest BV tests.");
  cmd->add_option("--size", o->size, "Image width and height (the paper: 512)")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--tile", o->tile, "Subregion size of table 1 (the paper: 8)")->check(CLI::Range(2, 512))->capture_default_str();
  cmd->add_option("--which", o->which, "1, 2 or both")->check(CLI::IsMember({"1", "2", "both"}))->capture_default_str();
  cmd->add_option("--csv", o->csv, "Write PREFIX1.csv and PREFIX2.csv (empty: no CSV)")->capture_default_str();
  cmd->add_option("--config", o->config, "Machine file whose [ops] costs and clock give the time (default: built-in GC-PowerPlus)")
      ->check(CLI::ExistingFile);
  cmd->callback([o] {
    const machine::MachineConfig config = o->config.empty() ? machine::default_machine_config() : machine::load_machine_config(o->config);
    std::vector<Scene> scenes;
    std::vector<Bvh> bvhs;
    for (auto name : paper::kScenes) {
      scenes.push_back(make_builtin_scene(name));
      bvhs.push_back(build_bvh_by_clustering(scenes.back()));
    }
    if (o->which != "2") {
      fmt::print("Table 1: primary rays, {}x{}, {}x{} subregions. Time: paper sun4/260 | ours, simulated on one {:.0f} MHz GC CPU "
                 "(host wall).\nBV and prim: tests per ray; total: all tests over the image, thousands. Paper | ours.\n\n",
                 o->size, o->size, o->tile, o->tile, config.clock_hz / 1e6);
      std::ofstream csv;
      if (!o->csv.empty()) {
        csv.open(o->csv + "1.csv");
        if (!csv) throw std::runtime_error("cannot write " + o->csv + "1.csv");
        csv << "algorithm,scene,photo,paper_time_s,sim_time_s,wall_time_s,paper_bv_per_ray,bv_per_ray,paper_prim_per_ray,"
               "prim_per_ray,paper_total_k,total_k,plane_tests,uniform_regions,uniformity_box_checks\n";
      }
      fmt::print("{:<4} {:<15} {:>8} {:>9} {:>8}  {:>6} {:>6}  {:>6} {:>6}  {:>7} {:>7}\n", "alg", "scene", "paper", "sim s",
                 "wall s", "BV", "", "prim", "", "total", "");
      for (const auto& row : paper::kTable1) {
        const Algorithm a = *parse_algorithm(row.algorithm);
        for (int s = 0; s < 5; ++s) {
          const Measured m = measure(scenes[s], bvhs[s], a, o->tile, o->size, config);
          const double rays = double(m.counters.primary_rays);
          const double bv = m.counters.primary_box_tests / rays, prim = m.counters.primary_prim_tests / rays;
          const double total = (m.counters.primary_box_tests + m.counters.primary_prim_tests) / 1e3;
          fmt::print("{:<4} {:<15} {:>8} {:>9.3f} {:>8.3f}  {:>6} {:>6.2f}  {:>6} {:>6.2f}  {:>7.0f} {:>7.0f}\n", row.algorithm,
                     paper::kScenes[s], min_sec(row.seconds[s]), m.simulated, m.wall, paper_value(row.bv_per_ray[s], 2),
                     bv, paper_value(row.prim_per_ray[s], 2), prim, row.total_thousands[s], total);
          if (csv.is_open())
            csv << fmt::format("{},{},{},{},{:.6f},{:.6f},{},{:.4f},{},{:.4f},{},{:.1f},{},{},{}\n", row.algorithm, paper::kScenes[s],
                               paper::kPhotos[s], row.seconds[s], m.simulated, m.wall,
                               row.bv_per_ray[s] < 0 ? "" : fmt::format("{}", row.bv_per_ray[s]), bv, row.prim_per_ray[s], prim,
                               row.total_thousands[s], total, m.counters.plane_tests, m.counters.uniform_regions,
                               m.counters.uniformity_box_checks);
        }
        fmt::print("\n");
      }
      if (csv.is_open()) fmt::print("csv       {}1.csv\n\n", o->csv);
    }
    if (o->which != "1") {
      fmt::print("Table 2: A4 time against subregion size. Paper sun4/260 | ours simulated on one GC CPU (s).\n\n");
      std::ofstream csv;
      if (!o->csv.empty()) {
        csv.open(o->csv + "2.csv");
        if (!csv) throw std::runtime_error("cannot write " + o->csv + "2.csv");
        csv << "tile,scene,photo,paper_time_s,sim_time_s,wall_time_s,bv_per_ray,prim_per_ray,plane_tests\n";
      }
      fmt::print("{:<6}", "tile");
      for (auto name : paper::kScenes) fmt::print(" {:>20}", name);
      fmt::print("\n");
      for (const auto& row : paper::kTable2) {
        fmt::print("{:<6}", fmt::format("{}x{}", row.tile, row.tile));
        for (int s = 0; s < 5; ++s) {
          const Measured m = measure(scenes[s], bvhs[s], Algorithm::A4, row.tile, o->size, config);
          fmt::print(" {:>9} | {:>8.3f}", min_sec(row.seconds[s]), m.simulated);
          const double rays = double(m.counters.primary_rays);
          if (csv.is_open())
            csv << fmt::format("{},{},{},{},{:.6f},{:.6f},{:.4f},{:.4f},{}\n", row.tile, paper::kScenes[s], paper::kPhotos[s],
                               row.seconds[s], m.simulated, m.wall, m.counters.primary_box_tests / rays,
                               m.counters.primary_prim_tests / rays, m.counters.plane_tests);
        }
        fmt::print("\n");
      }
      if (csv.is_open()) fmt::print("\ncsv       {}2.csv\n", o->csv);
    }
  });
}

// ---------------------------------------------------------------- sweep
void add_sweep(CommandGroups& g) {
  struct Opts {
    RenderOptions render;
    MachineOptions machine;
    std::string distribute = "dynamic";
    std::vector<int> nodes{1, 2, 4, 8, 16, 32, 64};
    std::string csv;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = g.sweep->add_subcommand(
      "raytrace",
      "Render the same image on 1..64 simulated nodes: simulated time, speedup over 1 node, parallel\n"
      "efficiency, mean communication time per node, and the host's wall time for each run.");
  add_render_options(cmd, o->render);
  add_machine_choice_options(cmd, o->machine);
  cmd->add_option("--distribute", o->distribute, "static, interleaved or dynamic (see run raytrace --help)")
      ->check(CLI::IsMember({"static", "interleaved", "dynamic"}))
      ->capture_default_str();
  cmd->add_option("--nodes,--node-counts", o->nodes, "Comma-separated node counts (as in sweep radiosity)")
      ->check(CLI::Range(1, 1 << 16))
      ->delimiter(',');
  cmd->add_option("--csv", o->csv, "Write the sweep as CSV");
  cmd->add_option("--json", o->machine.json, "Write the sweep as JSON");
  cmd->callback([o] {
    const Scene scene = load_scene_or_fail(o->render.scene);
    const Bvh bvh = build_bvh_by_clustering(scene);
    const RenderSettings settings = settings_of(o->render, scene);
    const Distribution d = *parse_distribution(o->distribute);
    print_scene(scene, bvh);
    fmt::print("render    {}x{}, {}, {}x{} subregions, {} distribution\n\n", settings.width, settings.height,
               paper_name_of(settings.algorithm), settings.tile, settings.tile, name_of(d));
    fmt::print("{:>6} {:>12} {:>8} {:>8} {:>12} {:>12} {:>9}\n", "nodes", "simulated s", "speedup", "effic.", "comm s/node",
               "compute s/nd", "wall s");
    std::ofstream csv;
    if (!o->csv.empty()) {
      csv.open(o->csv);
      if (!csv) throw std::runtime_error("cannot write " + o->csv);
      csv << "nodes,simulated_s,speedup,efficiency,comm_s_mean,compute_s_mean,wall_s\n";
    }
    nlohmann::json runs = nlohmann::json::array();
    double t1 = 0;
    for (int n : o->nodes) {
      MachineOptions m = o->machine;
      m.nodes = n;
      const parix::SimulationOptions sim = simulation_options(m, n);
      const ParallelRender r = render_parallel(scene, bvh, settings, d, sim);
      const double t = r.run.simulated_seconds();
      if (t1 == 0) t1 = t * n;  // the first count's time scaled to 1 node if the sweep does not start at 1
      const double speedup = t1 / t;
      fmt::print("{:>6} {:>12.4f} {:>8.2f} {:>7.0f}% {:>12.4f} {:>12.4f} {:>9.2f}\n", n, t, speedup, 100.0 * speedup / n,
                 r.run.mean_comm_seconds(), r.run.mean_compute_seconds(), r.run.wall_seconds);
      if (csv.is_open())
        csv << fmt::format("{},{:.6f},{:.4f},{:.4f},{:.6f},{:.6f},{:.4f}\n", n, t, speedup, speedup / n, r.run.mean_comm_seconds(),
                           r.run.mean_compute_seconds(), r.run.wall_seconds);
      nlohmann::json j = r.run.to_json();
      j["speedup"] = speedup;
      runs.push_back(j);
    }
    if (!o->machine.json.empty()) write_json_file(o->machine.json, {{"sweep", runs}, {"scene", scene.name}});
  });
}

// ---------------------------------------------------------------- bench
void add_bench(CommandGroups& g) {
  struct Opts {
    RenderOptions render;
    int repeat = 5;
    bool embree = true;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = g.bench->add_subcommand(
      "raytrace",
      "Host speed of primary rays: nearest hits for every pixel with the chosen algorithm on one thread,\n"
      "no shading, in millions of rays per second (best of --repeat runs; subtree and beam building included).");
  add_render_options(cmd, o->render, false);
  cmd->add_option("--repeat", o->repeat, "Runs; the best is reported")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_flag("!--no-embree", o->embree,
                "Skip the comparison with Intel Embree's rtcIntersect1 on the same rays (done when gcsim was built with libembree-dev)");
  cmd->callback([o] {
    const Scene scene = load_scene_or_fail(o->render.scene);
    const auto t0 = std::chrono::steady_clock::now();
    const Bvh bvh = build_bvh_by_clustering(scene);
    const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Algorithm a = *parse_algorithm(o->render.algo);
    print_scene(scene, bvh);
    fmt::print("build     {:.3f} s (clustering)\n", build);
    const int size = o->render.size;
    const Camera camera(scene.camera, size, size);
    const Tiling tiling{size, size, o->render.tile};
    double best = 1e30;
    std::int64_t checksum = 0;
    for (int rep = 0; rep < o->repeat; ++rep) {
      PrimaryTracer tracer(scene, bvh, camera, a);
      TraceCounters c;
      std::vector<Hit> hits;
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < tiling.count(); ++i) {
        const auto r = tiling.rect(i);
        tracer.trace_tile(r.x0, r.y0, r.x1, r.y1, hits, c);
        for (const Hit& h : hits) checksum += h.prim;
      }
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    const double rays = double(size) * size;
    fmt::print("bench     {} on {}x{}, {}x{} tiles: {:.3f} ms per frame, {:.2f} Mrays/s (one thread, best of {})\n",
               paper_name_of(a), size, size, o->render.tile, o->render.tile, best * 1e3, rays / best / 1e6, o->repeat);
    std::int64_t hits = 0;
    {
      PrimaryTracer tracer(scene, bvh, camera, a);
      TraceCounters c;
      std::vector<Hit> tile_hits;
      for (int i = 0; i < tiling.count(); ++i) {
        const auto r = tiling.rect(i);
        tracer.trace_tile(r.x0, r.y0, r.x1, r.y1, tile_hits, c);
        for (const Hit& h : tile_hits) hits += h.valid();
      }
    }
    if (o->embree) {
      const auto e = time_embree_primary_rays(scene, camera, o->repeat);
      if (!e) {
        fmt::print("embree    not available (gcsim was built without libembree-dev)\n");
      } else {
        fmt::print("embree    rtcIntersect1, one thread: {:.3f} ms per frame, {:.2f} Mrays/s; {} hits (ours {})\n",
                   e->seconds_per_frame * 1e3, rays / e->seconds_per_frame / 1e6, e->hits, hits);
        fmt::print("ratio     ours / Embree = {:.2f}\n", e->seconds_per_frame / best);
      }
    }
    (void)checksum;
  });
}

}  // namespace

void add_raytrace_commands(CommandGroups& g) {
  add_run(g);
  add_table(g);
  add_sweep(g);
  add_bench(g);
}

}  // namespace gcsim::cli
