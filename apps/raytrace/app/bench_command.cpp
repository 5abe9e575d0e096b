// gcsim bench raytrace: host speed of primary rays, next to Intel Embree when it is available.
#include <chrono>
#include <memory>

#include <fmt/format.h>

#include "apps/common/geometry/packet_traversal.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "apps/raytrace/algorithm.hpp"
#include "apps/raytrace/app/commands.hpp"
#include "apps/raytrace/app/render_options.hpp"
#include "apps/raytrace/bench_clock.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/embree_reference.hpp"
#include "apps/raytrace/primary_tracer.hpp"
#include "apps/raytrace/render.hpp"

namespace gcsim::raytrace::app {

namespace {

// The best of `repeat` frames of primary rays (nearest hits only), in packets or one ray at a time,
// in thread CPU time (bench_clock.hpp).
double best_frame_seconds(const Scene& scene, const Bvh& bvh, const Camera& camera, Algorithm a, const Tiling& tiling,
                          int repeat, bool packets) {
  double best = 1e30;
  for (int rep = 0; rep < repeat; ++rep) {
    PrimaryTracer tracer(scene, bvh, camera, a);
    tracer.use_packets(packets);
    TraceCounters c;
    std::vector<Hit> hits;
    const double start = bench_thread_seconds();
    for (int i = 0; i < tiling.count(); ++i) {
      const auto r = tiling.rect(i);
      tracer.trace_tile(r.x0, r.y0, r.x1, r.y1, hits, c);
    }
    best = std::min(best, bench_thread_seconds() - start);
  }
  return best;
}

}  // namespace

void add_bench_command(pipeline::CommandGroups& g) {
  struct Opts {
    RenderOptions render;
    int repeat = 5;
    bool embree = true;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = g.bench->add_subcommand(
      "raytrace",
      "Host speed of primary rays: nearest hits for every pixel with the chosen algorithm on one thread,\n"
      "no shading, in millions of rays per second (best of --repeat runs in thread CPU time; subtree and\n"
      "beam building included).\n"
      "A2-A4 trace primary rays in packets of 4 x 2 pixels; the single-ray core (what secondary, shadow\n"
      "and media rays use) is timed too. Both are compared with Embree's one ray at a time\n"
      "(rtcIntersect1); the packets also with its packets (rtcIntersect8).");
  add_render_options(cmd, o->render, false);
  cmd->add_option("--repeat", o->repeat, "Runs; the best is reported")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_flag("!--no-embree", o->embree,
                "Skip the comparison with Intel Embree on the same rays, one at a time (rtcIntersect1) and in 4 x 2 packets (rtcIntersect8), done when gcsim was built with libembree-dev");
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
    const bool packeted = a == Algorithm::A2 || a == Algorithm::A3 || a == Algorithm::A4;
    const double best = best_frame_seconds(scene, bvh, camera, a, tiling, o->repeat, true);
    // The single-ray core on its own: what secondary, shadow and media rays use.
    const double single = packeted ? best_frame_seconds(scene, bvh, camera, a, tiling, o->repeat, false) : best;
    const double rays = double(size) * size;
    fmt::print("bench     {} on {}x{}, {}x{} tiles: {:.3f} ms per frame, {:.2f} Mrays/s (one thread, best of {})\n",
               paper_name_of(a), size, size, o->render.tile, o->render.tile, best * 1e3, rays / best / 1e6, o->repeat);
    if (packeted) {
      fmt::print("kernel    {}\n", geometry::packet_kernel_vectorized()
                                        ? "packets of 4 x 2 pixels, eight AVX2 lanes (same counts as single rays)"
                                        : "packets traced one ray at a time (this host has no AVX2)");
      fmt::print("single    one ray at a time: {:.3f} ms per frame, {:.2f} Mrays/s\n", single * 1e3, rays / single / 1e6);
    }
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
        fmt::print("ratio     ours, one ray at a time / Embree = {:.2f}\n", e->seconds_per_frame / single);
        if (packeted) fmt::print("ratio     ours, packets / Embree = {:.2f}\n", e->seconds_per_frame / best);
        fmt::print("embree    rtcIntersect8, 4 x 2 pixel packets, one thread: {:.3f} ms per frame, {:.2f} Mrays/s; {} hits\n",
                   e->packet8_seconds_per_frame * 1e3, rays / e->packet8_seconds_per_frame / 1e6, e->packet8_hits);
        fmt::print("ratio     ours, packets / Embree packets = {:.2f}\n", e->packet8_seconds_per_frame / best);
      }
    }
  });
}

}  // namespace gcsim::raytrace::app
