#pragma once
// What the near field costs and buys (`gcsim accuracy radiosity` table 4): per near-field
// ratio (a shooter splits until each part is at most ratio x its distance to the nearest receiver,
// up to max_shooter_samples per side), the error on the two closed-form hard cases and the time of
// solving a real scene with it. The first row is the thesis's one point per shooter.
#include <functional>
#include <vector>

#include "apps/radiosity/progressive_solver.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::radiosity {

struct NearFieldAccuracy {
  double ratio;                    // HemicubeOptions::near_field_ratio; 0 in the one-point row
  int max_samples_per_side;        // 1 in the one-point row
  double facing_b, facing_exact;   // receiver of two facing unit squares at distance 1 (rho 0.5)
  double furnace_min, furnace_max; // closed box (rho 0.5, E 1): extreme elements, exact 2
  int scene_steps;
  double scene_simulated_seconds;  // the scene's progressive solve on one node (counted operations)
  double wall_seconds;             // host time of the whole row
  double facing_error() const { return facing_b / facing_exact - 1; }
  double furnace_min_error() const { return furnace_min / 2 - 1; }
  double furnace_max_error() const { return furnace_max / 2 - 1; }
};

// `options` gives the hemicube resolution, the samples cap, K and energy of the scene's solve; the
// hard cases are solved to convergence at the same resolution. One row with one point per shooter,
// then one per ratio.
std::vector<NearFieldAccuracy> near_field_accuracy(const Scene& scene, const SolverOptions& options,
                                                   const std::vector<double>& ratios,
                                                   const machine::MachineConfig& machine,
                                                   const std::function<void(const NearFieldAccuracy&)>& on_row = {});

}  // namespace gcsim::radiosity
