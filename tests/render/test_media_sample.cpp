// gcsim plan's media estimate by sampling: a fraction of the photons and of the view's tiles run on
// the simulated machine (the render's own programs) and are scaled up. A sample of every photon and
// every tile is the pass itself and predicts it exactly; a real sample lands near it; nothing the
// sample does reaches the render.
#include <gtest/gtest.h>

#include <filesystem>

#include "apps/common/scene/scene_file.hpp"
#include "apps/raytrace/parallel_render.hpp"
#include "apps/raytrace/tile_sample.hpp"
#include "apps/render/media_sample.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/plan_cost.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/sampled_view.hpp"
#include "apps/render/unified_render.hpp"
#include "apps/render/view_sample.hpp"
#include "machine/machine_config.hpp"
#include "tests/support/published_machine.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {
namespace {

using test_support::published_machine;

const std::string kSmall = (std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "media-small.toml").string();

struct Sampled {
  double photons_end = 0, view_start = 0, end = 0;
  apps::Image image;
};

// The render's program (no radiosity in MEDIA-SMALL), as `gcsim render` runs it.
Sampled render_sampled(const scene::SceneDescription& d, int nodes, std::size_t photons) {
  const Plan plan = make_plan(d);
  const RenderSetup setup = prepare_render(d, plan, kSmall, {}, photons);
  ViewSettings view;
  view.secondary = plan.pass(PassId::specular).on;
  view.shadows = plan.pass(PassId::shadows).on;
  UnifiedRender out(nodes);
  const parix::RunResult run = parix::run_simulated(published_machine(nodes), [&](parix::Processor& p) {
    unified_render_program(p, setup.split.surfaces, nullptr, {}, view, setup.media.get(), out);
  });
  finish(out);
  return {out.media_seconds(), out.view_start_seconds(), run.simulated_seconds(), out.view->result.image};
}

scene::SceneDescription small_scene() {
  scene::SceneDescription d = scene::load_scene_file(kSmall);
  d.image.width = 48, d.image.height = 32;  // 24 tiles
  return d;
}

TEST(MediaSample, ASampleOfEveryPhotonAndTilePredictsThePassExactly) {
  const scene::SceneDescription d = small_scene();
  const Plan plan = make_plan(d);
  ASSERT_TRUE(plan.pass(PassId::media).on);
  ASSERT_FALSE(plan.pass(PassId::radiosity).on);
  // 32 nodes: more than the 24 tiles, so who asks first decides which node gets which tile, and the
  // sample's nodes must start their view when the render's do (at their photon pass's end).
  for (int nodes : {1, 3, 32}) {
    SCOPED_TRACE(nodes);
    const MediaSample s = sample_media(d, plan, kSmall, published_machine(nodes), {.photons = 3000, .photon_divisor = 1, .tile_stride = 1, .row_stride = 1});
    ASSERT_EQ(s.tiles_rendered, s.tiles);
    const Sampled r = render_sampled(d, nodes, 3000);
    EXPECT_DOUBLE_EQ(s.photon_seconds, r.photons_end);
    // Each node reaches its start in whole cycles (12.5 ns at 80 MHz): the grid's end within two.
    EXPECT_NEAR(s.photon_seconds + s.grid_seconds, r.view_start, 2 / 80e6);
    EXPECT_DOUBLE_EQ(s.view_seconds, r.end - r.view_start);
    EXPECT_GT(s.march_seconds, 0.5 * s.view_seconds);  // the marching is most of this view
  }
}

// A real sample (1/8 and 1/16 of the photons, one run of tiles in 2) lands within 25 % of the
// render's photons, SH grid and view; the render afterwards is the render without a plan, pixel for pixel.
TEST(MediaSample, ASampleLandsNearThePassAndChangesNothingInTheRender) {
  const scene::SceneDescription d = small_scene();
  const Plan plan = make_plan(d);
  const Sampled before = render_sampled(d, 2, 8000);
  const MediaSample s = sample_media(d, plan, kSmall, published_machine(2), {.photons = 8000, .photon_divisor = 8, .tile_stride = 2});
  EXPECT_EQ(s.traced, 1000u);
  EXPECT_LT(s.tiles_rendered, s.tiles);
  const Sampled after = render_sampled(d, 2, 8000);
  const double predicted = s.photon_seconds + s.grid_seconds + s.view_seconds;
  EXPECT_NEAR(predicted, before.end, 0.25 * before.end);
  EXPECT_NEAR(s.photon_seconds, before.photons_end, 0.25 * before.photons_end);
  EXPECT_EQ(after.end, before.end);
  EXPECT_EQ(after.image.pixels(), before.image.pixels());
}

// The marching is measured on the view sample's tiles (raytrace/tile_sample.hpp): one run of 4 in k
// on diagonals, not single tiles. 6 x 4 tiles, one run in 2.
TEST(MediaSample, TheMarchingSampleRendersTheViewSamplesTiles) {
  const scene::SceneDescription d = small_scene();
  const Plan plan = make_plan(d);
  const raytrace::Tiling tiling{d.image.width, d.image.height, raytrace::RenderSettings{}.tile};
  const std::vector<int> runs = {4, 5, 6, 7, 8, 9, 16, 17, 18, 19, 20, 21};
  ASSERT_EQ(raytrace::sampled_tiles(tiling, 2, raytrace::kRunTiles), runs);
  const MediaSample s = sample_media(d, plan, kSmall, published_machine(2), {.photons = 2000, .photon_divisor = 4, .tile_stride = 2});
  EXPECT_EQ(s.rendered_tiles, runs);
  EXPECT_EQ(s.tiles_rendered, int(runs.size()));
  EXPECT_EQ(s.tiles, tiling.count());
  const ViewSample v = sample_view(d, plan, kSmall, published_machine(2), {.tile_stride = 2});
  EXPECT_EQ(v.rendered_tiles, runs);
}

// The plan's media row (photons, SH grid, marching) against the render's on a 96 x 64 view (96
// tiles) on 2 nodes, one run of tiles in 4: the render's marching is its view less the view without
// the media (a view sample of every tile). Measured: marching -1.3 %, media row -1.2 %.
TEST(MediaSample, ThePlansMediaRowLandsNearTheRenders) {
  scene::SceneDescription d = scene::load_scene_file(kSmall);
  d.image.width = 96, d.image.height = 64;
  const Plan plan = make_plan(d);
  const Sampled r = render_sampled(d, 2, 4000);
  const double marching = (r.end - r.view_start) - sample_view(d, plan, kSmall, published_machine(2), {.tile_stride = 1}).seconds();
  const MediaSample s = sample_media(d, plan, kSmall, published_machine(2), {.photons = 4000, .photon_divisor = 8, .tile_stride = 4});
  ASSERT_EQ(s.tiles_rendered * 4, s.tiles);
  EXPECT_NEAR(s.march_seconds, marching, 0.1 * marching);
  EXPECT_NEAR(s.seconds(), r.view_start + marching, 0.1 * (r.view_start + marching));
}

// One pixel row in 4 of every tile (the plan's choice where the sample is every tile of a small
// image) against every row, on the same tiles and photons: the photons and the SH grid are
// untouched, the marching moves by a few per cent (a tile's work is its pixels' radiance estimates,
// which its rows sample), and it is a sample, not a rerun of every row.
TEST(MediaSample, MarchingOneRowInFourLandsNearEveryRow) {
  const scene::SceneDescription d = small_scene();
  const Plan plan = make_plan(d);
  for (int nodes : {1, 4}) {
    SCOPED_TRACE(nodes);
    const MediaSampleOptions every{.photons = 4000, .photon_divisor = 4, .tile_stride = 1, .row_stride = 1};
    MediaSampleOptions chosen = every;
    chosen.row_stride = 0;
    const MediaSample a = sample_media(d, plan, kSmall, published_machine(nodes), every);
    const MediaSample b = sample_media(d, plan, kSmall, published_machine(nodes), chosen);
    EXPECT_EQ(b.row_stride, 4);
    EXPECT_EQ(b.rendered_tiles, a.rendered_tiles);
    EXPECT_EQ(b.photon_seconds, a.photon_seconds);
    EXPECT_EQ(b.grid_seconds, a.grid_seconds);
    EXPECT_NE(b.march_seconds, a.march_seconds);
    EXPECT_NEAR(b.march_seconds, a.march_seconds, 0.08 * a.march_seconds);
  }
}

// A quarter of the pixels marched; where a node has 4 tiles or more, an eighth where one row in 8 of
// the sampled tiles is still kMinPixelsMarchedThin pixels, a sixteenth where that is still
// kMinPixelsMarchedSixteenth: rows thin out only as far as the tiles do not.
TEST(MediaSample, TheRowStrideKeepsASixteenthAnEighthOrAQuarterOfThePixels) {
  const long vga = 640L * 480, quarter_vga = 320L * 240;
  EXPECT_EQ(march_row_stride(1, 4800, 8, vga), 16);
  EXPECT_EQ(march_row_stride(2, 4800, 8, vga), 8);
  EXPECT_EQ(march_row_stride(3, 4800, 8, vga), 5);
  EXPECT_EQ(march_row_stride(4, 4800, 8, vga), 4);
  EXPECT_EQ(march_row_stride(8, 4800, 8, vga), 2);
  EXPECT_EQ(march_row_stride(16, 4800, 8, vga), 1);
  EXPECT_EQ(march_row_stride(1, 4800, 1201, vga), 4);  // fewer than 4 tiles a node
  EXPECT_EQ(march_row_stride(1, 4800, 1200, vga), 16);
  EXPECT_EQ(march_row_stride(1, 4800, 0, vga), 16);  // no nodes counts as one
  EXPECT_EQ(march_row_stride(1, 1200, 1, quarter_vga), 8);  // a sixteenth would be 4800 pixels
  EXPECT_EQ(march_row_stride(4, 1200, 1, quarter_vga), 1);  // one row in 8 of its tiles: 2400
  EXPECT_EQ(march_row_stride(1, 4096, 1, 16 * kMinPixelsMarchedSixteenth), 16);
  EXPECT_EQ(march_row_stride(1, 4096, 1, 16 * kMinPixelsMarchedSixteenth - 1), 8);
  EXPECT_EQ(march_row_stride(1, 48, 1, 64 * 48), 4);  // an eighth would be 384 pixels
  EXPECT_EQ(march_row_stride(1, 512, 1, 8 * kMinPixelsMarchedThin), 8);
  EXPECT_EQ(march_row_stride(1, 512, 1, 8 * kMinPixelsMarchedThin - 1), 4);
  EXPECT_EQ(march_row_stride(2, 512, 1, 16 * kMinPixelsMarchedThin - 1), 2);
}

TEST(MediaSample, TheSameSampleTwiceGivesTheSameFigures) {
  const scene::SceneDescription d = small_scene();
  const Plan plan = make_plan(d);
  const MediaSampleOptions o{.photons = 4000, .photon_divisor = 4, .tile_stride = 3};
  const MediaSample a = sample_media(d, plan, kSmall, published_machine(3), o), b = sample_media(d, plan, kSmall, published_machine(3), o);
  EXPECT_EQ(a.photon_seconds, b.photon_seconds);
  EXPECT_EQ(a.grid_seconds, b.grid_seconds);
  EXPECT_EQ(a.march_seconds, b.march_seconds);
  EXPECT_EQ(a.map_bytes, b.map_bytes);
}

// CORNELL-FOG's photons leave light on the walls: the sample scales it to every photon for the
// radiosity sample (the render's pass starts from it and takes 190 loops instead of 171).
TEST(MediaSample, WallDepositsAreScaledToEveryPhoton) {
  const auto file = (std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "cornell-fog.toml").string();
  scene::SceneDescription d = scene::load_scene_file(file);
  d.image.width = d.image.height = 32;
  const Plan plan = make_plan(d);
  const MediaSample all = sample_media(d, plan, file, published_machine(2), {.photons = 4000, .photon_divisor = 1});
  const MediaSample part = sample_media(d, plan, file, published_machine(2), {.photons = 4000, .photon_divisor = 4});
  ASSERT_FALSE(all.wall_power.empty());
  ASSERT_EQ(all.wall_power.size(), part.wall_power.size());
  double sum_all = 0, sum_part = 0;
  for (std::size_t e = 0; e < all.wall_power.size(); ++e)
    sum_all += radiosity::channel_sum(all.wall_power[e]), sum_part += radiosity::channel_sum(part.wall_power[e]);
  EXPECT_NEAR(sum_part, sum_all, 0.2 * sum_all);
}

// The marching sample's stride: at least 8 tiles a node, at most 4, and up to 8 (with 16 a node)
// only where a medium covers the image: CORNELL-FOG's fog box does, `example.toml`'s smoke ball
// does not (one in 8 put its marching 26 % high on 8 nodes).
TEST(MediaSample, TheMarchingStrideWidensOnlyWhereAMediumFillsTheImage) {
  EXPECT_EQ(march_tile_stride(1024, 64, false), 2);  // 16 tiles a node: one run in 2, not every tile
  EXPECT_EQ(march_tile_stride(1024, 64, true), 2);
  EXPECT_EQ(march_tile_stride(1024, 8, false), 4);
  EXPECT_EQ(march_tile_stride(1024, 8, true), 8);
  EXPECT_EQ(march_tile_stride(48, 8, true), 1);  // fewer than 8 tiles a node: every tile
  const auto coverage = [](const char* file) {
    return make_plan(scene::load_scene_file((std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / file).string()))
        .facts.media_coverage;
  };
  EXPECT_EQ(coverage("cornell-fog.toml"), 1.0);
  EXPECT_EQ(coverage("media-exp1.toml"), 1.0);
  EXPECT_LT(coverage("example.toml"), 1.0);
  EXPECT_GT(coverage("example.toml"), 0.0);
  EXPECT_EQ(coverage("cornell.toml"), 0.0);  // no medium
}

}  // namespace
}  // namespace gcsim::render
