// gcsim plan's radiosity loops: forecast by a coarse host solve of the mesh, each loop priced by the
// sample's loops that projected as many hemicubes.
#include <gtest/gtest.h>

#include <filesystem>

#include "apps/common/scene/scene_file.hpp"
#include "apps/render/loop_forecast.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/render_setup.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::render {
namespace {

// Loops of 1 and 2 hemicubes took 1 s and 2 s in the sample: a forecast of 1, 2, 2 costs 5 s; a class
// the sample never saw (4 hemicubes) is priced per hemicube by the sample's mean (3 s over 3).
TEST(LoopForecast, PricesEachLoopByTheSampleLoopsWithItsHemicubes) {
  LoopForecast f;
  f.hemicubes = {1, 2, 2};
  const LoopPricing p = price_loops(f, {1.0, 2.0, 1.0, 2.0}, {1, 2, 1, 2});
  EXPECT_DOUBLE_EQ(p.seconds, 5.0);
  EXPECT_DOUBLE_EQ(p.relative_uncertainty, kForecastLoopSpread);  // no spread in the sample's times
  f.hemicubes = {4};
  EXPECT_DOUBLE_EQ(price_loops(f, {1.0, 2.0}, {1, 2}).seconds, 4.0);
  // Spread loop times widen the uncertainty beyond the loops' own spread.
  f.hemicubes = {1, 1};
  EXPECT_GT(price_loops(f, {0.8, 1.2, 1.0}, {1, 1, 1}).relative_uncertainty, kForecastLoopSpread);
}

// The coarse solve of example.toml's mesh (with its fog between the walls) takes the loops the
// render's pass takes at 256 cells across, the pass run here in full on the simulated machine.
TEST(LoopForecast, ACoarseSolveTakesThePassLoops) {
  const auto file = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "example.toml";
  const scene::SceneDescription d = scene::load_scene_file(file);
  const Plan plan = make_plan(d);
  const RenderSetup setup = prepare_render(d, plan, file.string());
  radiosity::ParallelOptions o;
  o.solver.hemicube.resolution = 256;
  o.solver.energy = 0.999;
  o.solver.media = setup.radiosity_media_or_null();
  o = radiosity::with_shared_projections(o);
  int loops = 0;
  parix::run_simulated(test_support::published_machine(2), [&](parix::Processor& p) {
    const radiosity::ParallelOutcome out = radiosity::solve_replica(p, setup.mesh, o);
    if (p.id() == 0) loops = int(out.steps.size());
  });
  const LoopForecast f = forecast_loops(setup.mesh, o.solver, hemicubes_per_patch(setup.mesh, o.solver.hemicube));
  EXPECT_TRUE(f.converged);
  EXPECT_NEAR(f.loops(), loops, 0.1 * loops);
  // A coarse hemicube sees the same mesh: the loop count does not hinge on the resolution.
  const LoopForecast finer =
      forecast_loops(setup.mesh, o.solver, hemicubes_per_patch(setup.mesh, o.solver.hemicube), 2 * kForecastResolution);
  EXPECT_NEAR(finer.loops(), f.loops(), 0.1 * loops);
}

}  // namespace
}  // namespace gcsim::render
