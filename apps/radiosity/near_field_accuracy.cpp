#include "apps/radiosity/near_field_accuracy.hpp"

#include <algorithm>

#include "apps/radiosity/accuracy.hpp"
#include "apps/radiosity/analytic_form_factors.hpp"
#include "apps/radiosity/hard_case_scenes.hpp"

namespace gcsim::radiosity {

namespace {

constexpr double kRho = 0.5;

// Converged to within 1e-6 of the limit: what is left is the form factors' error.
SolverOptions converged(SolverOptions o) {
  o.energy = 1 - 1e-6;
  o.shooters = 1;
  return o;
}

}  // namespace

std::vector<NearFieldAccuracy> near_field_accuracy(const Scene& scene, const SolverOptions& options,
                                                   const std::vector<double>& ratios,
                                                   const machine::MachineConfig& machine,
                                                   const std::function<void(const NearFieldAccuracy&)>& on_row) {
  const Scene facing = facing_unit_squares(1.0, kRho);
  const Scene furnace = closed_box(1.0, 4, 2, kRho, 1.0);
  std::vector<NearFieldAccuracy> out;
  for (std::size_t k = 0; k <= ratios.size(); ++k) {
    const double t0 = now_seconds();
    SolverOptions o = options;
    if (k == 0) o.hemicube.max_shooter_samples = 1;
    else o.hemicube.near_field_ratio = ratios[k - 1];
    NearFieldAccuracy row{};
    row.ratio = k == 0 ? 0.0 : ratios[k - 1];
    row.max_samples_per_side = o.hemicube.max_shooter_samples;
    row.facing_exact = kRho * parallel_rectangles_form_factor(1, 1, 1);
    OpCounts ops;
    const auto poll = [&](const StepRecord&, const ProgressiveState&) { stop_if_interrupted(ops, machine); };
    row.facing_b = solve_progressive(facing, converged(o), &ops, poll).state.element_radiosity()[1].r;
    const auto box = solve_progressive(furnace, converged(o), &ops, poll).state.element_radiosity();
    const auto [lo, hi] = std::minmax_element(box.begin(), box.end(), [](const Rgb& a, const Rgb& b) { return a.r < b.r; });
    row.furnace_min = lo->r, row.furnace_max = hi->r;
    ops = OpCounts{};
    row.scene_steps = int(solve_progressive(scene, o, &ops, poll).steps.size());
    row.scene_simulated_seconds = simulated_seconds(ops, machine);
    row.wall_seconds = now_seconds() - t0;
    out.push_back(row);
    if (on_row) on_row(row);
  }
  return out;
}

}  // namespace gcsim::radiosity
