#include "apps/render/loop_forecast.hpp"

#include <chrono>
#include <cmath>
#include <map>

namespace gcsim::render {

std::vector<int> hemicubes_per_patch(const radiosity::Scene& mesh, const radiosity::HemicubeOptions& o,
                                     radiosity::SamplesPerSideMemo* memo) {
  // The largest samples per side the hemicube renderer gives its grids at o.resolution (each sample's
  // hemicube o.resolution / n across, at least 16 and a whole number of cells: hemicube.cpp).
  int max_per_side = 1;
  for (int n = 2; n <= o.max_shooter_samples; n *= 2) {
    const int r = o.resolution / n, scale = 1 << o.hierarchical_levels;
    if (!(r >= 16 && r % (2 * scale) == 0 && r / scale >= o.cells_per_side)) break;
    max_per_side = n;
  }
  std::vector<int> out = memo ? *memo->get(mesh, o.near_field_ratio, max_per_side)
                              : radiosity::shooter_samples_per_side(mesh, o.near_field_ratio, max_per_side);
  for (int& n : out) n *= n;
  return out;
}

LoopForecast forecast_loops(const radiosity::Scene& mesh, radiosity::SolverOptions solver,
                            const std::vector<int>& hemicubes_per_patch, int resolution) {
  const auto start = std::chrono::steady_clock::now();
  solver.hemicube.resolution = resolution;
  solver.hemicube.cells_per_side = kForecastCellsPerSide;
  solver.max_steps = radiosity::SolverOptions{}.max_steps;
  const radiosity::SolveResult solved = radiosity::solve_progressive(mesh, solver);
  LoopForecast f;
  f.converged = solved.converged;
  for (const radiosity::StepRecord& step : solved.steps) {
    int h = 0;
    for (int patch : step.shooters) h += hemicubes_per_patch[std::size_t(patch)];
    f.hemicubes.push_back(h);
  }
  f.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return f;
}

namespace {
struct LoopClass {
  double sum = 0, sum_sq = 0;
  int n = 0;
  double mean() const { return sum / n; }
};
}  // namespace

LoopPricing price_loops(const LoopForecast& f, const std::vector<double>& loop_seconds,
                        const std::vector<int>& sample_hemicubes) {
  LoopPricing p;
  if (loop_seconds.empty()) return p;
  // The sample's loops by their hemicubes; a class the sample did not see is priced per hemicube by
  // the sample's mean (the projection and cell work grow with the hemicubes, the update does not).
  std::map<int, LoopClass> classes;
  double all = 0;
  int all_hemicubes = 0;
  for (std::size_t i = 0; i < loop_seconds.size(); ++i) {
    LoopClass& c = classes[sample_hemicubes[i]];
    c.sum += loop_seconds[i], c.sum_sq += loop_seconds[i] * loop_seconds[i], ++c.n;
    all += loop_seconds[i], all_hemicubes += sample_hemicubes[i];
  }
  const double per_hemicube = all_hemicubes > 0 ? all / all_hemicubes : all / double(loop_seconds.size());
  std::map<int, int> forecast_count;
  for (int h : f.hemicubes) {
    const auto it = classes.find(h);
    if (it == classes.end()) {
      p.seconds += per_hemicube * std::max(h, 1);
      continue;
    }
    p.seconds += it->second.mean();
    ++forecast_count[h];
  }
  // Each class's mean is known to its standard error from the sample's loops; the forecast's loops
  // of a class all take that mean, so its error counts once per loop. The loop count itself moved by
  // up to 2 % with the coarse hemicube's resolution (8, 16, 24 across: CORNELL 264, 258, 260).
  double mean_error = 0;
  for (auto [h, count] : forecast_count) {
    const LoopClass& c = classes[h];
    const double sd = c.n > 1 ? std::sqrt(std::max(0.0, c.sum_sq / c.n - c.mean() * c.mean()) * c.n / (c.n - 1)) : c.mean();
    mean_error += count * sd / std::sqrt(double(c.n));
  }
  const double timing = p.seconds > 0 ? mean_error / p.seconds : 0.0;
  p.relative_uncertainty = std::sqrt(timing * timing + kForecastLoopSpread * kForecastLoopSpread);
  return p;
}

}  // namespace gcsim::render
