#pragma once
// What accuracy costs: hemicube resolution against closed-form form factors, and the energy
// threshold of progressive refinement against a converged (Gauss-Seidel) reference. Each row carries
// the simulated seconds the work would take on one node of the machine (from counted operations)
// and the host's wall seconds.
//
// These loops run outside the simulated machine, so they poll parix::host::interruption_requested()
// themselves (between hemicubes and solver steps) and throw parix::host::Interrupted; each finished row is
// handed to `on_row` first, so a command can keep the rows done before an interruption.
#include <functional>
#include <vector>

#include "apps/radiosity/analytic_form_factors.hpp"
#include "apps/radiosity/progressive_solver.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::radiosity {

struct FormFactorAccuracy {
  FormFactorCase form_factor_case;
  int resolution;
  double hemicube_point, exact_point;  // from the centre of the source (one hemicube)
  double hemicube_area, exact_area;    // squares: mean of 8 x 8 hemicubes, area to area; disc: the ideal disc
  double simulated_seconds, wall_seconds;
  double point_error() const { return std::abs(hemicube_point - exact_point) / exact_point; }
  double area_error() const { return std::abs(hemicube_area - exact_area) / exact_area; }
};

std::vector<FormFactorAccuracy> form_factor_accuracy(const std::vector<int>& resolutions,
                                                     const machine::MachineConfig& machine,
                                                     const std::function<void(const FormFactorAccuracy&)>& on_row = {});

struct EnergyAccuracy {
  double threshold;
  int steps;
  double rms_relative_error;  // area-weighted RMS of |B - B_ref| / mean B_ref over elements
  double max_relative_error;  // worst element, relative to the mean reference radiosity
  double simulated_seconds, wall_seconds;
};

// One progressive run, measured as it passes each threshold (ascending), against Gauss-Seidel.
std::vector<EnergyAccuracy> energy_accuracy(const Scene& scene, const SolverOptions& options,
                                            const std::vector<double>& thresholds,
                                            const machine::MachineConfig& machine,
                                            const std::function<void(const EnergyAccuracy&)>& on_row = {});

struct HierarchicalAccuracy {
  int levels;                 // 0: the fixed hemicube (the reference)
  int steps;
  double rms_relative_error;  // against the fixed hemicube of the same resolution
  double max_relative_error;
  double simulated_seconds, wall_seconds;
};

// The hierarchical hemicube (thesis 4.5) against the fixed one at the same resolution: what the
// adaptive sampling saves and what it costs in accuracy, per number of levels.
std::vector<HierarchicalAccuracy> hierarchical_accuracy(const Scene& scene, const SolverOptions& options,
                                                        const std::vector<int>& levels,
                                                        const machine::MachineConfig& machine,
                                                        const std::function<void(const HierarchicalAccuracy&)>& on_row = {});

// Simulated seconds of counted work on one CPU of the machine.
double simulated_seconds(const OpCounts& ops, const machine::MachineConfig& machine);

// The host's steady clock in seconds, for the tables' wall-time columns.
double now_seconds();

// Throws parix::host::Interrupted once SIGINT/SIGTERM asked (parix/host/interruption.hpp), with the counted
// work so far as the simulated time reached: the accuracy loops run outside the simulation, so
// they poll this after every solver step.
void stop_if_interrupted(const OpCounts& ops, const machine::MachineConfig& machine);

}  // namespace gcsim::radiosity
