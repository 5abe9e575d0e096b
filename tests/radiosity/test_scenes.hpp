#pragma once
// Small scenes for the radiosity tests.
#include "apps/radiosity/hard_case_scenes.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/scene.hpp"
#include "parix/run_result.hpp"

namespace gcsim::radiosity::testing {

// The furnace box of hard_case_scenes.hpp (a closed cube, faces looking inwards).
using radiosity::closed_box;
// A unit room (scaled by `scale`) lit by a small ceiling light, with a block on the floor and a thin
// panel hovering `gap` above the floor (nearly coplanar when gap is tiny).
Scene lit_room(double scale = 1.0, double gap = 0.05, double rho = 0.6);

// Quick parallel runs: hemicube 32 in 4 x 4 top cells (16 + 4 x 8 = 48 cells), to 90 %.
ParallelOptions quick_parallel_options(parix::BcastAlgo bcast);
// One run of the radiosity program on the published machine cut to `nodes` nodes.
struct SimulatedRun {
  ParallelOutcome out;
  parix::RunResult result;
};
SimulatedRun run_published(const Scene& scene, const ParallelOptions& o, int nodes);

}  // namespace gcsim::radiosity::testing
