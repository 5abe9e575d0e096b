// gcsim plan's radiosity estimate by sampling: the pass's first loops run on the simulated machine.
// A sample that runs to convergence is the pass itself, so it predicts the pass's time exactly; the
// loop count extrapolates a geometric decline of the unshot energy.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "apps/common/scene/scene_file.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/plan_cost.hpp"
#include "apps/render/radiosity_sample.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/unified_render.hpp"
#include "machine/machine_config.hpp"
#include "tests/support/published_machine.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {
namespace {

using test_support::published_machine;

TEST(RadiositySample, ExtrapolatesAGeometricDeclineToItsEnd) {
  std::vector<radiosity::StepRecord> steps;
  for (int k = 1; k <= 8; ++k) steps.push_back({k, 1 - std::pow(0.5, k), {}});
  EXPECT_NEAR(extrapolate_loops(steps, 0.999), std::log2(1000.0), 1e-9);
  steps.resize(3);
  EXPECT_EQ(extrapolate_loops(steps, 0.999), 0.0);  // too few loops to see a decline
}

// example.toml's radiosity converges in 18 loops: a sample of 40 is the whole pass, and the plan's
// estimate is then the render's radiosity pass time (within rounding), on 1 and 4 nodes.
TEST(RadiositySample, ASampleThatConvergesPredictsThePassExactly) {
  const auto file = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "example.toml";
  const scene::SceneDescription d = scene::load_scene_file(file);
  const Plan plan = make_plan(d);
  ASSERT_TRUE(plan.pass(PassId::radiosity).on);
  for (int nodes : {1, 4}) {
    SCOPED_TRACE(nodes);
    const RadiositySample s = sample_radiosity_loops(d, file.string(), published_machine(nodes), 40);
    ASSERT_LT(s.loops, 40);
    EXPECT_EQ(s.expected_loops, s.loops);
    CostModel model;
    model.radiosity_seconds_per_loop = s.seconds_per_loop;
    model.radiosity_loops = s.expected_loops;
    const double predicted =
        estimate_pass(plan.pass(PassId::radiosity), plan.facts, published_machine(nodes).config, nodes, model).seconds_per_node;
    // The render's radiosity pass on the same machine, without the view.
    const RenderSetup setup = prepare_render(d, plan, file.string());
    radiosity::ParallelOptions o;
    o.solver.hemicube.resolution = 256;
    o.solver.energy = 0.999;
    o.solver.media = setup.radiosity_media_or_null();  // example.toml's fog, as the render's pass
    o = radiosity::with_shared_projections(o);
    const parix::RunResult run = parix::run_simulated(published_machine(nodes), [&](parix::Processor& p) {
      radiosity::solve_replica(p, setup.mesh, o);
    });
    EXPECT_NEAR(predicted, run.simulated_seconds(), 1e-9 * run.simulated_seconds());
  }
}

}  // namespace
}  // namespace gcsim::render
