// A picture too big for one node's memory that fits on eight: with the static
// distribution every node holds the scene and the packed pixels of its share of the tiles, node 0
// also the image it assembles and the others' pixels that reach it before it takes them. On nodes
// that hold the scene, the image and three quarters of the image's packed pixels more, one node
// (all the pixels) fails at once naming what it holds; on eight, node 0's own eighth and what
// waits for it fit.
#include <gtest/gtest.h>

#include <string>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/parallel_render.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::raytrace {
namespace {

TEST(ParallelNodeMemory, APictureTooBigForOneNodeFitsOnEight) {
  const Scene s = make_builtin_scene("teapots");
  const Bvh bvh = build_bvh_by_clustering(s);
  RenderSettings rs;
  rs.width = rs.height = 128;
  const ParallelRenderJob job(s, bvh, rs, Distribution::static_blocks);
  machine::MachineConfig small = machine::published_machine_config();
  small.memory_bytes = job.scene_bytes() + job.image_bytes() + job.tile_bytes() + job.image_bytes() * 3 / 4;
  auto on = [&](int nodes) {
    parix::SimulationOptions o;
    o.config = machine::with_nodes(small, nodes);
    return o;
  };
  try {
    render_parallel(s, bvh, rs, Distribution::static_blocks, on(1));
    FAIL() << "the whole picture fitted on one node";
  } catch (const parix::OutOfMemoryError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("processor 0: out of node memory: rendered tiles"), std::string::npos) << what;
    EXPECT_NE(what.find("image "), std::string::npos) << what;
  }
  const ParallelRender eight = render_parallel(s, bvh, rs, Distribution::static_blocks, on(8));
  EXPECT_LE(eight.run.memory_peak, small.memory_bytes);
  EXPECT_GT(eight.run.memory_peak, job.scene_bytes() + job.image_bytes());  // node 0: its tiles too
  EXPECT_EQ(eight.counters.primary_rays, rs.width * rs.height);
}

}  // namespace
}  // namespace gcsim::raytrace
