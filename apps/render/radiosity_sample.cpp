#include "apps/render/radiosity_sample.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/loop_forecast.hpp"
#include "apps/render/medium_region.hpp"
#include "apps/render/radiosity_media.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

double extrapolate_loops(const std::vector<radiosity::StepRecord>& steps, double energy) {
  const std::size_t n = steps.size();
  if (n < 4) return 0;
  const double unshot_mid = 1 - steps[n / 2 - 1].shot_fraction, unshot_end = 1 - steps[n - 1].shot_fraction;
  if (!(unshot_end > 0 && unshot_end < unshot_mid)) return 0;
  const double per_loop = std::log(unshot_end / unshot_mid) / double(n - n / 2);  // < 0
  return double(n) + std::max(0.0, std::log((1 - energy) / unshot_end) / per_loop);
}

RadiositySample sample_radiosity_loops(const scene::SceneDescription& d, const std::string& file,
                                       const parix::SimulationOptions& machine, int loops,
                                       const std::vector<radiosity::Rgb>* received) {
  const auto start = std::chrono::steady_clock::now();
  // The mesh and options of `gcsim render`'s radiosity pass (render_app.cpp, render_setup.cpp).
  const SplitScene split = split_media(d, file);
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(split.surfaces));
  const std::unique_ptr<RadiosityMedia> media = RadiosityMedia::of(split.media);  // as prepare_render's
  radiosity::ParallelOptions options;
  options.solver.media = media.get();
  options.solver.hemicube.resolution = 256;
  options.solver.energy = 0.999;
  options.solver.max_steps = loops;
  options = radiosity::with_shared_projections(options);
  std::vector<radiosity::StepRecord> steps;
  bool converged = false;
  if (received && !received->empty()) options.solver.received = received;
  std::vector<double> loop_ends;  // node 0's clock after each loop
  const parix::RunResult run = parix::run_simulated(machine, [&](parix::Processor& p) {
    radiosity::ParallelOptions mine = options;
    if (p.id() == 0) mine.on_loop = [&](int, double) { loop_ends.push_back(p.now_seconds()); };
    radiosity::ParallelOutcome out = radiosity::solve_replica(p, mesh, mine);
    if (p.id() == 0) steps = std::move(out.steps), converged = out.converged;
  });
  RadiositySample s;
  s.loops = int(steps.size());
  s.extrapolated_loops = converged ? s.loops : extrapolate_loops(steps, options.solver.energy);
  if (converged || s.loops == 0) {  // the sample is the pass
    s.expected_loops = s.loops, s.seconds = run.simulated_seconds();
  } else {
    const std::vector<int> per_patch = hemicubes_per_patch(
        mesh, radiosity::hemicube_of(options), options.shared_projections ? &options.shared_projections->samples_per_side() : nullptr);
    const LoopForecast forecast = forecast_loops(mesh, options.solver, per_patch);
    std::vector<double> loop_seconds;
    std::vector<int> loop_hemicubes;
    for (std::size_t i = 0; i < loop_ends.size() && i < steps.size(); ++i) {
      loop_seconds.push_back(loop_ends[i] - (i > 0 ? loop_ends[i - 1] : 0.0));
      int h = 0;
      for (int patch : steps[i].shooters) h += per_patch[std::size_t(patch)];
      loop_hemicubes.push_back(h);
    }
    const LoopPricing price = price_loops(forecast, loop_seconds, loop_hemicubes);
    // The pass ends when its last node does: the sample's lag of the last node after node 0 kept.
    const double lag = loop_ends.empty() ? 0.0 : std::max(0.0, run.simulated_seconds() - loop_ends.back());
    s.expected_loops = forecast.loops();
    s.seconds = price.seconds + lag;
    s.relative_uncertainty = price.relative_uncertainty;
  }
  s.peak_bytes = run.memory_peak;
  s.seconds_per_loop = s.expected_loops > 0 ? s.seconds / s.expected_loops : 0.0;
  s.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace gcsim::render
