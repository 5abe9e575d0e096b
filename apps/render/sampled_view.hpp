#pragma once
// One run of the render's view program (view_pass.hpp: the ray tracer's dynamic distribution, pixels
// to node 0) on the simulated machine over a sample of the view's tiles, and its time scaled to every
// tile: what `gcsim plan`'s view sample (view_sample.hpp) and the media's marching sample
// (media_sample.hpp) both measure, on the same tiles (raytrace/tile_sample.hpp).
#include <cstdint>
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/view_pass.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

// The tiles of d's image as the render's view cuts it (RenderSettings' tile size).
int view_tile_count(const scene::SceneDescription& d);
// The stride the plan's samples take by default: one run of tiles in at most 4, and at least 16
// tiles a node. Mirrors and glass sit in a few tiles: one in 8 put CORNELL-MIRROR-GLASS's specular
// rays 33 % low on 1 node (one in 4: 4 %).
int sample_tile_stride(int tiles, int nodes);

// The media sample's stride. Its marching is most of the plan's host time. At least 8 tiles a node
// (at 16 the 256 x 256 views sampled every tile on 64 nodes: CORNELL-FOG 5.2 s of the plan's CPU
// against the render's 11 s; at 8 one run in 2, the marching +4 % against every tile's, one in 4
// +19 %), one run in at most 4; where a medium covers the whole image (fills_view) one in up to 8
// with at least 16 tiles a node (CORNELL-FOG's marching +3 % on 8 nodes, -0.7 % on 1; MEDIA-EXP1's
// -1 % on 8), while `example.toml`'s small smoke ball sits in a few tiles (one in 8: +14 and +26 %).
int march_tile_stride(int tiles, int nodes, bool fills_view);

// What the sampled view meets. media: the view's media, or null (the view without them). photons:
// the media pass's photons per medium (its SH grids are built from them), or null: the render's
// photon pass runs first (nothing charged for an absorbing medium: no photons). grid_scale: the SH
// grids' counts, charged before the view as the render does, scaled by this.
struct SampledViewInput {
  const RenderSetup* setup = nullptr;
  const std::vector<radiosity::Rgb>* radiosity = nullptr;  // per element, or null: no radiosity pass
  ViewSettings view;
  const MediaSetup* media = nullptr;
  const std::vector<std::vector<media::Photon>>* photons = nullptr;
  double grid_scale = 1.0;
  int tile_stride = 1;
  int pixel_row_stride = 1;  // one pixel row in k of each tile traced, its counts scaled (ParallelRenderJob::sample_pixel_rows)
  // When each node reaches its view (before its SH grid share), as the render's: there the view
  // starts where the node's photon pass ends, and who asks node 0 for tiles first decides which node
  // gets which tile. Empty: every node at 0.
  std::vector<double> node_start;
};

struct SampledView {
  double seconds = 0;       // the view as the render reports it: the end less the last node's start
  double compute = 0;       // the nodes' mean CPU time in it (before it: the SH grid's share, left out)
  double grid_seconds = 0;  // the SH grid's share: the last node's start of the view less the last node_start
  std::int64_t peak = 0;    // the largest node's memory
  int tiles = 0, rendered = 0;
  std::vector<int> rendered_tiles;  // which, in index order
  double exposure = 0;      // the view's, kept so the next run need not compute it again

  // Scaled to every tile: the nodes' mean work grows with the tiles, the rest (the last tiles'
  // imbalance, the start and the final messages) stays. Scaling the whole time scaled the imbalance
  // of a short run too: 8 nodes, one tile in 8, +31 to +47 % on CORNELL and CORNELL-MIRROR-GLASS.
  double scaled() const;
};

// machine: cut to the nodes of the estimate.
SampledView run_sampled_view(const SampledViewInput& in, const parix::SimulationOptions& machine);

}  // namespace gcsim::render
