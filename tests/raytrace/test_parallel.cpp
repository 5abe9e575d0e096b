// The image assembled on node 0 of the simulated GC is the sequential image, whatever the
// distribution and node count, and simulated time is deterministic.
#include <gtest/gtest.h>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/parallel_render.hpp"
#include "apps/raytrace/pixel_encoding.hpp"
#include "apps/raytrace/render.hpp"
#include "machine/machine_config.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::raytrace {
namespace {

TEST(Parallel, EveryDistributionAssemblesTheSequentialImage) {
  const Scene s = make_builtin_scene("teapots");
  const Bvh bvh = build_bvh_by_clustering(s);
  RenderSettings rs;
  rs.width = rs.height = 64;
  rs.algorithm = Algorithm::A4;
  const RenderOutput seq = render_image(s, bvh, rs);
  for (Distribution d : {Distribution::static_blocks, Distribution::interleaved, Distribution::dynamic}) {
    for (int nodes : {1, 3, 8}) {
      const ParallelRender par = render_parallel(s, bvh, rs, d, test_support::published_machine(nodes));
      int differ = 0;
      for (int y = 0; y < rs.height; ++y)
        for (int x = 0; x < rs.width; ++x)
          for (int k = 0; k < 3; ++k)
            differ += encode_srgb8(seq.image.at(x, y)[k]) != encode_srgb8(par.image.at(x, y)[k]);
      EXPECT_EQ(differ, 0) << name_of(d) << " on " << nodes << " nodes";
      EXPECT_EQ(par.prim_ids, seq.prim_ids);
      EXPECT_EQ(par.counters.primary_rays, rs.width * rs.height);
      int tiles = 0;
      for (int t : par.tiles_per_node) tiles += t;
      EXPECT_EQ(tiles, (Tiling{rs.width, rs.height, rs.tile}.count()));
      EXPECT_GT(par.run.makespan, 0);
    }
  }
}

TEST(Parallel, SimulatedTimeIsDeterministicAndFallsWithNodes) {
  const Scene s = make_builtin_scene("spheres-random");
  const Bvh bvh = build_bvh_by_clustering(s);
  RenderSettings rs;
  rs.width = rs.height = 96;
  const auto a = render_parallel(s, bvh, rs, Distribution::dynamic, test_support::published_machine(4));
  const auto b = render_parallel(s, bvh, rs, Distribution::dynamic, test_support::published_machine(4));
  EXPECT_EQ(a.run.makespan, b.run.makespan);
  EXPECT_EQ(a.tiles_per_node, b.tiles_per_node);
  const auto one = render_parallel(s, bvh, rs, Distribution::dynamic, test_support::published_machine(1));
  EXPECT_LT(a.run.makespan, one.run.makespan);
}

// --host-threads: workers render tiles ahead (tile_prefetch.hpp); every algorithm but B1, every
// distribution, local and Whitted shading give the same pixels, counts per node and simulated
// times as one host thread.
TEST(Parallel, HostThreadsChangeNothingButWallTime) {
  std::int64_t by_workers = 0;
  for (const char* scene : {"teapots", "whitted"}) {
    const Scene s = make_builtin_scene(scene);
    const Bvh bvh = build_bvh_by_clustering(s);
    for (Algorithm a : {Algorithm::A1, Algorithm::A2, Algorithm::A2p, Algorithm::A3, Algorithm::A4}) {
      RenderSettings rs;
      rs.width = rs.height = 48;
      rs.algorithm = a;
      if (std::string(scene) == "whitted") rs.shading = Shading::whitted;
      for (Distribution d : {Distribution::static_blocks, Distribution::interleaved, Distribution::dynamic}) {
        for (int nodes : {1, 5}) {
          const ParallelRender one = render_parallel(s, bvh, rs, d, test_support::published_machine(nodes));
          for (int threads : {2, 4}) {
            SCOPED_TRACE(::testing::Message() << scene << " " << name_of(a) << " " << name_of(d) << " on " << nodes
                                            << " nodes, " << threads << " host threads");
            const ParallelRender more = render_parallel(s, bvh, rs, d, test_support::published_machine(nodes), threads);
            EXPECT_EQ(more.prim_ids, one.prim_ids);
            EXPECT_TRUE(more.image.pixels() == one.image.pixels());
            EXPECT_EQ(more.run.makespan, one.run.makespan);
            EXPECT_EQ(more.run.events, one.run.events);
            ASSERT_EQ(more.per_node.size(), one.per_node.size());
            for (std::size_t n = 0; n < one.per_node.size(); ++n) {
              EXPECT_EQ(more.per_node[n].ops(), one.per_node[n].ops()) << "node " << n;
              EXPECT_EQ(more.tiles_per_node[n], one.tiles_per_node[n]) << "node " << n;
            }
            by_workers += more.tiles_by_workers;
          }
        }
      }
    }
  }
  EXPECT_GT(by_workers, 0);  // which tiles depends on the host's timing
}

TEST(PixelEncoding, RoundTripsEveryCode) {
  for (int k = 0; k < 256; ++k) EXPECT_EQ(encode_srgb8(decode_srgb8(std::uint8_t(k))), k);
}

}  // namespace
}  // namespace gcsim::raytrace
