#pragma once
// What accuracy costs across a whole render (`gcsim accuracy render`): each pass's main control
// varied from the default with the others held, every render on the simulated machine at the
// reference's exposure, its image compared with a high-quality reference render.
#include <cstdint>
#include <string>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/scene/scene_description.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/render_setup.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

// The main control of each pass that runs today.
struct RenderControls {
  int hemicube = 256;     // radiosity: hemicube resolution
  double energy = 0.999;  // radiosity: fraction of the energy shot
  int max_depth = 5;      // specular: reflection and refraction levels
  std::size_t photons = kDefaultPhotons;  // media: photons emitted
  double march = 32;      // media: distance samples per free path (M = march (1 - T) on a segment)
  bool media = true;      // false: the media are left out (an error budget may drop them)
  std::uint64_t seed = 1;  // media: the photons' and the distance samples' random streams
};
RenderControls reference_controls();  // hemicube 512, energy 0.9999, depth 10, 200000 photons, march 128

struct RenderRun {
  apps::Image image;  // as node 0 assembled it (8-bit sRGB decoded to linear)
  double exposure = 1.0;
  double simulated_s = 0, wall_s = 0;
};

// One render of the scene's plan (radiosity when on, then the view) with these controls;
// exposure 0 chooses it automatically (the reference's is then reused by every other render).
RenderRun render_with(const scene::SceneDescription& description, const Plan& plan, const RenderControls& controls,
                      double exposure, const parix::SimulationOptions& machine);

// sqrt(mean over pixels and channels of (image - reference)^2) / mean of the reference: 0 for the
// same image. Throws std::invalid_argument if the sizes differ.
double relative_rmse(const apps::Image& image, const apps::Image& reference);

// One varied control: the pass it belongs to, its name and the values tried (the default among them).
struct ControlSweep {
  PassId pass;
  std::string control;
  std::vector<double> values;
};
// The controls of the passes the plan runs; quick: fewer values.
std::vector<ControlSweep> control_sweeps(const Plan& plan, bool quick);
RenderControls with_control(RenderControls c, const std::string& control, double value);

}  // namespace gcsim::render
