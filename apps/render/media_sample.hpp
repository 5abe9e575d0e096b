#pragma once
// The media pass's cost measured rather than counted, as radiosity_sample.hpp does for radiosity:
// the render's own per-node programs run on the simulated machine on a sample, and `gcsim plan`
// scales it up.
//   photons  each node traces the first 1/d of its share (the photons a full pass traces), then the
//            all-gather and the wall deposits' reduction, as the render; run at 1/(2d) too, the pass
//            is taken as linear in the photons (tracing and gathered bytes) through the two points,
//            which keeps a fixed part (latencies, the deposits' all-reduce) fixed.
//   SH grid  built on the host from the sample's photons; its counts scaled to all photons (its
//            voxels and their photons grow with the map, eq. 13), each node charged its share.
//   marching the view's sample as view_sample.hpp takes it (sampled_view.hpp: one run of 4 tiles in
//            k, on diagonals, the nodes' mean CPU time scaled to every tile, the waiting kept),
//            rendered with the media (from the sample's photons) and without: the difference (the
//            set-up cancels), one pixel row in 16, 8 or 4 of each sampled tile, its counts scaled to
//            the tile (march_row_stride). Single tiles, the whole time scaled, put example.toml's marching
//            23 % high on 8 nodes (1.53 s against 1.25 s).
//            Without a radiosity pass each node starts its view where its photon pass ends (each
//            node's end through the two points), as in the render: which node asks for tiles first
//            decides which gets which (MEDIA-SMALL, 64 nodes: +57 % when every node started at 0).
// The radiosity pass reads what the photons leave on the walls: the sample's deposits, scaled to
// all photons, go to its sample (radiosity_sample.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/plan.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

struct MediaSampleOptions {
  std::size_t photons = 50000;  // the render's (--photons); render_setup.hpp's kDefaultPhotons
  int photon_divisor = 8;       // the sample traces photons / this, and half of that; 1: every photon
  int tile_stride = 0;          // one run of tiles in k; 0: chosen (march_tile_stride); 1: every tile
  int row_stride = 0;           // one pixel row in k of each sampled tile marched; 0: chosen (march_row_stride); 1: every row
};

// The marching's pixel rows, chosen for a sample that marches one run of tiles in K: one in
// max(1, 4 / K) of each sampled tile, a quarter of the image's pixels; where a node has 4 tiles or
// more, one in max(1, 8 / K), an eighth, where one row in 8 of the sampled tiles is still
// kMinPixelsMarchedThin pixels, and one in max(1, 16 / K), a sixteenth, where that is still
// kMinPixelsMarchedSixteenth pixels. One row in 8 put MEDIA-SMALL (64 x 48: 384 pixels marched)
// -13 % low on 1 node and its view on 64 nodes (48 tiles) +10.5 % high (+6.1 % at one in 4). A
// sixteenth of MEDIA-EXP1 (640 x 480: 19200 pixels) moved its view by +0.2, -0.1 and -0.2 points
// on 1, 8 and 64 nodes against an eighth, for half the plan's host time. Moving the first row from
// tile to tile made MEDIA-SMALL -5 % on 1 node but put a 48 x 32 MEDIA-SMALL's marching -11.5 % low
// at one row in 4 (-39 % at one in 8): on few pixels the rows' choice decides, so the sample keeps
// the tile's top row and enough pixels. On top of one run of tiles in 4, one row in 4 from the top
// put a 96 x 64 MEDIA-SMALL's marching +15 % high (apps/render/README.md).
inline constexpr long kMinPixelsMarchedThin = 4096;
inline constexpr long kMinPixelsMarchedSixteenth = 16384;
int march_row_stride(int tile_stride, int tiles, int nodes, long pixels);

struct MediaSample {
  double photon_seconds = 0;  // the photon pass (last node's end), extrapolated to every photon
  double grid_seconds = 0;    // the SH grid's share (slowest node), counts scaled to every photon
  double view_seconds = 0;    // the whole view with the media, scaled to every tile
  double march_seconds = 0;   // of which the media's: with minus without, scaled to every tile
  std::int64_t map_bytes = 0;  // the photon map every node holds, scaled to every photon
  std::vector<radiosity::Rgb> wall_power;  // the deposits scaled to every photon (empty: none)
  std::size_t traced = 0;     // photons of the larger sample
  int tile_stride = 1, tiles_rendered = 0, tiles = 0;
  int row_stride = 1;         // pixel rows: one in this many of each sampled tile
  std::vector<int> rendered_tiles;  // which (raytrace/tile_sample.hpp), in index order
  double host_seconds = 0;    // wall time the samples took
  double seconds() const { return photon_seconds + grid_seconds + march_seconds; }  // the plan's media pass
};

// machine: cut to the nodes of the estimate. file: for messages. Throws std::invalid_argument where
// the render would refuse the scene (the plan then keeps the operation count).
MediaSample sample_media(const scene::SceneDescription& d, const Plan& plan, const std::string& file,
                         const parix::SimulationOptions& machine, const MediaSampleOptions& o = {});

}  // namespace gcsim::render
