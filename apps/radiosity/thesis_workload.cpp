#include "apps/radiosity/thesis_workload.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "apps/radiosity/thesis_tables.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::radiosity {

std::optional<int> thesis_loops(const std::string& scene, double energy) {
  const thesis::SceneFigures* f = thesis::figures_for(scene);
  if (!f) return std::nullopt;
  for (std::size_t i = 0; i < thesis::kEnergyPercent.size(); ++i)
    if (std::abs(thesis::kEnergyPercent[i] - 100 * energy) < 1e-9 && f->loops_for_energy[i] > 0)
      return f->loops_for_energy[i];
  return std::nullopt;
}

Scene with_reflectances_scaled(Scene scene, double s) {
  for (auto& surface : scene.surfaces) {
    surface.reflectance *= s;
    for (int c = 0; c < 3; ++c)
      if (!(surface.reflectance[c] < 1.0))
        throw std::invalid_argument("a reflectance scaled by " + std::to_string(s) + " reaches 1");
  }
  return scene;
}

double largest_reflectance_scale(const Scene& scene) {
  double most = 0;
  for (const auto& surface : scene.surfaces)
    most = std::max({most, surface.reflectance.r, surface.reflectance.g, surface.reflectance.b});
  return most > 0 ? 0.999 / most : 1.0;
}

namespace {

// Loops of the scaled scene to the options' energy; more than `cap` loops reads as cap + 1, so
// that a bisection step stops as soon as it knows the answer is "more".
int loops_at(const Scene& scene, SolverOptions o, double s, int cap) {
  o.max_steps = cap;
  // A matching solves a dozen times on the host before any simulation: SIGINT stops it between loops.
  const SolveResult r = solve_progressive(
      with_reflectances_scaled(scene, s), o, nullptr,
      [](const StepRecord&, const ProgressiveState&) { parix::host::throw_if_interrupted(); });
  return r.converged ? r.state.steps() : cap + 1;
}

}  // namespace

LoopMatch match_loops(const Scene& scene, const SolverOptions& options, int target) {
  constexpr int kUncapped = 1 << 24;
  LoopMatch m;
  m.thesis_loops = target;
  m.loops_as_built = loops_at(scene, options, 1.0, kUncapped);
  if (m.loops_as_built == target) {
    m.loops = target;
    return m;
  }
  // Bracket: loops(lo) < target <= loops(hi), halved ten times (a few 1e-4 of reflectance).
  double lo = 0.5, hi = largest_reflectance_scale(scene);
  if (m.loops_as_built > target) hi = 1.0;
  else lo = 1.0;
  const int cap = target + 1;
  int loops_lo = m.loops_as_built < target ? m.loops_as_built : loops_at(scene, options, lo, cap);
  int loops_hi = m.loops_as_built > target ? cap : loops_at(scene, options, hi, cap);
  if (loops_hi < target || loops_lo >= target) {  // out of reach: the nearer end
    m.scale = loops_hi < target ? hi : lo;
    m.loops = loops_at(scene, options, m.scale, kUncapped);
    return m;
  }
  for (int i = 0; i < 10; ++i) {
    const double mid = 0.5 * (lo + hi);
    const int l = loops_at(scene, options, mid, cap);
    if (l >= target) hi = mid, loops_hi = l;
    else lo = mid, loops_lo = l;
  }
  // hi reaches the target (exactly, or one loop or more past it); lo stops short of it.
  const int hi_loops = loops_hi == target ? target : loops_at(scene, options, hi, kUncapped);
  const bool take_hi = hi_loops - target <= target - loops_lo;
  m.scale = take_hi ? hi : lo;
  m.loops = take_hi ? hi_loops : loops_lo;
  return m;
}

}  // namespace gcsim::radiosity
