#pragma once
// The radiosity pass's loops and their cost, forecast from the mesh itself. Extrapolating the
// first loops' decline of the unshot energy missed CORNELL by a quarter (193 loops against 254): the
// decline slows once the lamp's light is shot and the walls pass it on. Instead the same mesh, media
// and received power are solved to convergence on the host with a coarse hemicube: the shooters it
// picks and how fast the energy goes follow the mesh's reflectances and form factors, which a
// coarse hemicube already resolves (CORNELL 258 loops at 16 cells across against 254 at 256, in
// 0.05 s of host time). Later loops cost more than early ones where their shooters are large
// patches near their receivers (near-field shooters project 4 hemicubes, shooter_samples.hpp), so
// each forecast loop is priced by the sample's loops with the same count of hemicubes.
#include <vector>

#include "apps/radiosity/radiosity.hpp"

namespace gcsim::render {

struct LoopForecast {
  std::vector<int> hemicubes;  // per forecast loop: the hemicubes its shooters project
  bool converged = false;      // the coarse solve reached the energy fraction
  double host_seconds = 0;
  int loops() const { return int(hemicubes.size()); }
};

// The hemicube resolution of the coarse solve: 16 cells across (8 gives CORNELL 264 loops, 24 260).
inline constexpr int kForecastResolution = 16;
// The coarse hemicube is one cell of 8 x 8 pixels a face quarter: the render's parallel partition
// (8 cells per side) would cut 16 pixels into cells of 2 x 2, each walking every polygon of its face.
inline constexpr int kForecastCellsPerSide = 2;
inline constexpr double kForecastLoopSpread = 0.02;  // relative, of the loops between those resolutions

// Solves `mesh` on the host as `solver` would, with a coarse hemicube `resolution` across.
// hemicubes_per_patch: the render's near-field samples per patch squared (its hemicube resolution's).
LoopForecast forecast_loops(const radiosity::Scene& mesh, radiosity::SolverOptions solver,
                            const std::vector<int>& hemicubes_per_patch, int resolution = kForecastResolution);

// The hemicubes each patch projects when it shoots at `o`'s resolution (near-field samples squared).
// memo: the run's (its replicas worked the samples out already), or null.
std::vector<int> hemicubes_per_patch(const radiosity::Scene& mesh, const radiosity::HemicubeOptions& o,
                                     radiosity::SamplesPerSideMemo* memo = nullptr);

// A forecast priced by a sample of the pass's loops: loop i of the sample took loop_seconds[i]
// simulated and projected sample_hemicubes[i] hemicubes.
struct LoopPricing {
  double seconds = 0;              // the forecast's loops summed
  double relative_uncertainty = 0; // the sample's loop times' standard errors and the loops' spread, as a fraction
};
LoopPricing price_loops(const LoopForecast& f, const std::vector<double>& loop_seconds,
                        const std::vector<int>& sample_hemicubes);

}  // namespace gcsim::render
