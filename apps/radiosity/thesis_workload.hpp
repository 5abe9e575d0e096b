#pragma once
// The thesis's scenes as its runs converged. Table 4.2 gives the loops each scene took to shoot a
// fraction of its energy; our scenes are rebuilt from table 4.1's counts and published geometry,
// and converge in a different number of loops (CORNELL: 254 to 99.9 % against the thesis's 302).
// A run's time is its loops times the time of a loop, and only the second is the machine's: a
// validation that mixed the two would blame the machine for the scene. The thesis does not give
// its reflectances, so the workload is matched by one factor per scene: every reflectance of the
// scene scaled by the s whose sequential solve takes table 4.2's loop count at the run's energy.
// Emission and geometry are unchanged.
#include <optional>
#include <string>

#include "apps/radiosity/radiosity.hpp"

namespace gcsim::radiosity {

struct LoopMatch {
  double scale = 1.0;     // every reflectance of the scene times this
  int loops = 0;          // loops of the scaled scene to the run's energy
  int loops_as_built = 0; // loops of the scene as built (scale 1)
  int thesis_loops = 0;   // table 4.2's figure
};

// Table 4.2's loops for a built-in scene (case-insensitive) at this energy fraction, or nothing
// (a scene or an energy the table does not report).
std::optional<int> thesis_loops(const std::string& scene, double energy);

// The scene with every surface's reflectance multiplied by s (each channel below 1 required).
Scene with_reflectances_scaled(Scene scene, double s);

// The largest factor every reflectance of the scene can take and stay below 1.
double largest_reflectance_scale(const Scene& scene);

// The factor whose sequential solve (options: the runs' hemicube, shooters and energy) takes the
// loop count closest to `target`, by bisection between 0.5 and largest_reflectance_scale (the loop
// count grows with the reflectances). Deterministic: the same scene and options give the same s.
LoopMatch match_loops(const Scene& scene, const SolverOptions& options, int target);

}  // namespace gcsim::radiosity
