#pragma once
// The view pass's cost measured rather than counted, as media_sample.hpp does for the media: the
// render's own view program (view_pass.hpp, the ray tracer's dynamic distribution over the nodes,
// pixels to node 0) runs on the simulated machine on one run of 4 tiles in k, on diagonals, the
// nodes' mean CPU time scaled by the tiles over those rendered, the rest kept (sampled_view.hpp, the
// same tiles and scaling as the media's marching sample). The rows of `gcsim plan` are split by running the sample with the plan's rays
// added one kind at a time:
//   view      primary rays and their shading alone
//   specular  what the reflected and refracted rays add (the plan's specular pass is on)
//   shadows   what the shadow rays add (on), at every hit, secondary ones included
// so the three add up to the view as the render casts it. With the media pass on, the sample runs
// without the media: their marching is the media pass's (media_sample.hpp). An absorbing medium
// with no photon pass stays in: its transmittance is the view's own work.
#include <cstdint>
#include <string>
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/plan.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

struct ViewSampleOptions {
  int tile_stride = 0;  // one run of tiles in k; 0: chosen (sample_tile_stride); 1: every tile
};

struct ViewSample {
  double view_seconds = 0;      // primary rays, scaled to every tile
  double specular_seconds = 0;  // added by reflected and refracted rays (0: the pass is off)
  double shadow_seconds = 0;    // added by shadow rays (0: off)
  std::int64_t bytes_per_node = 0;  // the largest node's memory in the view (scene, tree; node 0's image)
  int tile_stride = 1, tiles_rendered = 0, tiles = 0;
  std::vector<int> rendered_tiles;  // which (raytrace/tile_sample.hpp), in index order
  int runs = 0;                 // sample runs on the simulated machine (one per kind of ray)
  double host_seconds = 0;      // wall time the runs took
  double seconds() const { return view_seconds + specular_seconds + shadow_seconds; }
};

// What the view shows on each element before radiosity has run: its emission. The view's work does
// not depend on the radiosities (the same triangles, the same rays), only its colours do.
std::vector<radiosity::Rgb> emitted_radiosity(const radiosity::Scene& mesh);

// machine: cut to the nodes of the estimate. file: for messages. Throws std::invalid_argument where
// the render would refuse the scene (the plan then keeps the operation count).
ViewSample sample_view(const scene::SceneDescription& d, const Plan& plan, const std::string& file,
                       const parix::SimulationOptions& machine, const ViewSampleOptions& o = {});

}  // namespace gcsim::render
