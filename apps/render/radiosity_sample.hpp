#pragma once
// The radiosity pass's cost measured rather than counted: its first loops run on the simulated
// machine (the radiosity app's own program, stopped after a few loops), so the time per loop
// includes what an operation count misses, the repeated work, the communication and the waiting,
// as SMPI predicts a run from a sample of it. `gcsim plan` multiplies it by the expected loops.
#include <cstdint>
#include <string>
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

struct RadiositySample {
  int loops = 0;                 // loops run (fewer if the solve converged sooner)
  double host_seconds = 0;       // wall time the sample and the forecast took
  // Loops to shoot the energy fraction: the sample's own where it converged, else the coarse host
  // solve's (loop_forecast.hpp).
  double expected_loops = 0;
  // The old forecast, for comparison: the unshot energy taken to keep falling by the factor per loop
  // it fell by over the sample's second half (CORNELL: 193 loops against 254).
  double extrapolated_loops = 0;
  double seconds = 0;            // the pass, predicted: the forecast's loops priced by the sample's
  double seconds_per_loop = 0;   // seconds over expected_loops
  double relative_uncertainty = 0;  // of seconds, from the spread of the sample's loop times
  std::int64_t peak_bytes = 0;   // the most a node held (replica and hemicube: the pass's own)
};

// The loops a progressive solve needs to shoot `energy`, from the steps it made so far: the unshot
// energy taken to keep falling by the factor per loop it fell by over their second half (0 with
// fewer than 4 steps or no decline).
double extrapolate_loops(const std::vector<radiosity::StepRecord>& steps, double energy);

// machine: the machine already cut to the nodes of the estimate. file: for messages. received: what
// the photon pass leaves on each element (media_sample.hpp), which the render's pass starts from and
// which makes it longer (CORNELL-FOG: 190 loops instead of 171); null or empty: none.
RadiositySample sample_radiosity_loops(const scene::SceneDescription& d, const std::string& file,
                                       const parix::SimulationOptions& machine, int loops = 8,
                                       const std::vector<radiosity::Rgb>* received = nullptr);

}  // namespace gcsim::render
