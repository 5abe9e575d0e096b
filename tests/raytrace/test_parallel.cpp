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

TEST(PixelEncoding, RoundTripsEveryCode) {
  for (int k = 0; k < 256; ++k) EXPECT_EQ(encode_srgb8(decode_srgb8(std::uint8_t(k))), k);
}

}  // namespace
}  // namespace gcsim::raytrace
