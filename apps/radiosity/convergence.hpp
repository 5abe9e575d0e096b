#pragma once
// Runs that cannot or did not converge: refused up front, or reported as failures.
#include <optional>
#include <string>

#include "apps/radiosity/hemicube.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// Throws std::invalid_argument when progressive refinement can never reach a shot fraction below 1:
// a channel in which every surface reflects everything (reflectance exactly 1) and something emits,
// in a closed scene (the form factors from the brightest emitter sum to 1, so no light escapes
// either). The message names the surface and says why.
void check_energy_can_be_absorbed(const Scene& scene, const HemicubeOptions& hemicube);

// Empty when the run reached its threshold; otherwise why it did not (the step limit, or nothing
// left to shoot), for the caller to print and exit non-zero.
std::optional<std::string> convergence_failure(bool converged, double shot_fraction, double threshold, int steps,
                                               int max_steps);

}  // namespace gcsim::radiosity
