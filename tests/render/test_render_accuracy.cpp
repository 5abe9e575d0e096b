// gcsim accuracy render's parts: the image error, the controls, and that spending more on a
// control brings the render closer to the reference.
#include <gtest/gtest.h>

#include <filesystem>

#include "apps/common/scene/scene_file.hpp"
#include "apps/render/error_budget.hpp"
#include "apps/render/render_accuracy.hpp"

namespace gcsim::render {
namespace {

scene::SceneDescription scene_without_media(scene::SceneDescription d) {
  std::erase_if(d.shapes, [&](const scene::Shape& s) { return d.materials.at(std::size_t(s.material)).medium.has_value(); });
  return d;
}

apps::Image constant(float v) {
  apps::Image im(4, 3);
  for (auto& p : im.pixels()) p = glm::vec3(v);
  return im;
}

TEST(RenderAccuracy, RelativeRmseOfKnownImages) {
  EXPECT_EQ(relative_rmse(constant(0.5f), constant(0.5f)), 0.0);
  EXPECT_DOUBLE_EQ(relative_rmse(constant(1.0f), constant(2.0f)), 0.5);  // |1 - 2| / 2
  EXPECT_THROW(relative_rmse(apps::Image(2, 2), constant(1.0f)), std::invalid_argument);
}

TEST(RenderAccuracy, ControlsFollowThePlan) {
  const auto dir = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes";
  const Plan cornell = make_plan(scene::load_scene_file(dir / "cornell.toml"));
  const Plan mirror = make_plan(scene::load_scene_file(dir / "cornell-mirror-glass.toml"));
  const Plan direct = make_plan(scene::load_scene_file(dir / "direct-light.toml"));
  EXPECT_EQ(control_sweeps(cornell, false).size(), 2u);  // hemicube, energy
  EXPECT_EQ(control_sweeps(mirror, false).size(), 3u);   // and the reflection depth
  EXPECT_TRUE(control_sweeps(direct, false).empty());
  EXPECT_EQ(with_control({}, "energy", 0.9).energy, 0.9);
  EXPECT_THROW(with_control({}, "spp", 4), std::invalid_argument);
}

// On a small CORNELL: the reference rendered twice is the same image (error exactly 0), and
// shooting more of the energy brings the render monotonically closer to it, at more simulated time.
TEST(RenderAccuracy, MoreEnergyShotIsCloserAndCostsMore) {
  auto d = scene::load_scene_file(std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "cornell.toml");
  d.image.width = d.image.height = 48;
  const Plan plan = make_plan(d);
  parix::SimulationOptions machine;
  machine.config = machine::with_nodes(machine::published_machine_config(), 2);
  const RenderControls reference{32, 0.99, 5};
  const RenderRun ref = render_with(d, plan, reference, 0, machine);
  EXPECT_EQ(relative_rmse(render_with(d, plan, reference, ref.exposure, machine).image, ref.image), 0.0);
  double last_error = 1e9, last_time = 0;
  for (double energy : {0.5, 0.8, 0.95}) {
    const RenderRun r = render_with(d, plan, {32, energy, 5}, ref.exposure, machine);
    const double e = relative_rmse(r.image, ref.image);
    EXPECT_LT(e, last_error) << energy;
    EXPECT_GT(r.simulated_s, last_time) << energy;
    last_error = e, last_time = r.simulated_s;
  }
  EXPECT_GT(last_error, 0.0);
}

TEST(ErrorBudget, CoarsensWhatItsEstimatesAllow) {
  const auto dir = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes";
  auto d = scene::load_scene_file(dir / "cornell-mirror-glass.toml");
  const Plan plan = make_plan(d);
  EXPECT_THROW(controls_for_budget(d, plan, 0.0), std::invalid_argument);
  EXPECT_THROW(controls_for_budget(d, plan, 1.0), std::invalid_argument);
  const BudgetChoice tight = controls_for_budget(d, plan, 0.001), loose = controls_for_budget(d, plan, 0.05);
  EXPECT_LT(loose.controls.energy, tight.controls.energy);
  EXPECT_LE(tight.controls.energy, RenderControls{}.energy);
  EXPECT_EQ(loose.controls.max_depth, 5);  // 0.95^5 is far above 0.05
  for (auto& m : d.materials) m.mirror = std::min(m.mirror, 0.5), m.transmittance = std::min(m.transmittance, 0.5);
  EXPECT_EQ(controls_for_budget(d, make_plan(d), 0.1).controls.max_depth, 4);  // 0.5^4 < 0.1 <= 0.5^3
}

// Media are dropped only when thin: CORNELL-FOG's fog (optical depth 0.96 along the box's diagonal)
// stays at any budget; a haze 10000 times thinner goes at 0.02 (measured: relative RMSE 0.0136 against
// the full plan, with the radiosity coarsened by the rest of the budget); a haze 100 times thinner
// stays, because near the lamp (64 times the mean surface) its glow outshines the walls (dropping it
// alone changed the image by 0.024).
TEST(ErrorBudget, DropsOnlyMediaTooThinToMatter) {
  const auto dir = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes";
  auto d = scene::load_scene_file(dir / "cornell-fog.toml");
  EXPECT_TRUE(controls_for_budget(d, make_plan(d), 0.1).controls.media);
  auto thinned = [&](double factor) {
    scene::SceneDescription t = d;
    for (auto& m : t.materials)
      if (m.medium) m.medium->sigma_s *= factor, m.medium->sigma_a *= factor;
    return t;
  };
  const auto haze = thinned(1e-2), faint = thinned(1e-4);
  EXPECT_TRUE(controls_for_budget(haze, make_plan(haze), 0.02).controls.media);
  const BudgetChoice dropped = controls_for_budget(faint, make_plan(faint), 0.02);
  EXPECT_FALSE(dropped.controls.media);
  // What the media took of the budget is not left to the radiosity: it shoots more than at 0.02.
  EXPECT_GT(dropped.controls.energy, controls_for_budget(scene_without_media(d), make_plan(scene_without_media(d)), 0.02).controls.energy);
}

// The budget's estimate holds on CORNELL: the coarsened render is within the budget of the full
// plan's image (same exposure), and cheaper.
TEST(ErrorBudget, CornellStaysWithinItsBudget) {
  auto d = scene::load_scene_file(std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "cornell.toml");
  d.image.width = d.image.height = 48;
  const Plan plan = make_plan(d);
  parix::SimulationOptions machine;
  machine.config = machine::with_nodes(machine::published_machine_config(), 2);
  const RenderRun full = render_with(d, plan, {32, 0.999, 5}, 0, machine);
  for (double budget : {0.01, 0.03, 0.1}) {
    RenderControls c = controls_for_budget(d, plan, budget).controls;
    c.hemicube = 32;
    const RenderRun r = render_with(d, plan, c, full.exposure, machine);
    EXPECT_LE(relative_rmse(r.image, full.image), budget) << budget;
    EXPECT_LT(r.simulated_s, full.simulated_s) << budget;
  }
}

}  // namespace
}  // namespace gcsim::render
