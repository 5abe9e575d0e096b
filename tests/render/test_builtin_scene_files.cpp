// The built-in scene files of scenes/: every one loads and lowers, and cornell.toml is the radiosity
// app's built-in CORNELL polygon by polygon (table 4.1's counts, the same patches and elements in the
// same order, the same surfaces), so radiosity gives it the same solution.
#include <gtest/gtest.h>

#include <filesystem>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/scene.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::scene {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes";

TEST(BuiltinSceneFiles, EveryFileLoadsAndFlattensForRadiosity) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".toml") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    const SceneDescription d = load_scene_file(entry.path());
    EXPECT_FALSE(d.shapes.empty());
    EXPECT_TRUE(d.camera.has_value());
    const radiosity::Scene s = radiosity::flatten(to_world(d));
    EXPECT_GT(s.elements.size(), 0u);
  }
  EXPECT_GE(files, 6);
}

void expect_same_polygon(const geometry::Polygon& a, const geometry::Polygon& b) {
  ASSERT_EQ(a.count, b.count);
  for (int k = 0; k < a.count; ++k) EXPECT_EQ(a.v[k], b.v[k]) << "vertex " << k;
}

TEST(BuiltinSceneFiles, CornellFileIsTheBuiltInCornell) {
  const radiosity::Scene from_file = radiosity::flatten(to_world(load_scene_file(kScenes / "cornell.toml")));
  const radiosity::Scene built_in = radiosity::flatten(radiosity::cornell_world());
  EXPECT_EQ(from_file.counts(), radiosity::thesis_counts("cornell"));  // 8 / 9 / 112 / 166 / 274
  EXPECT_EQ(from_file.counts(), built_in.counts());
  ASSERT_EQ(from_file.patches.size(), built_in.patches.size());
  for (std::size_t i = 0; i < built_in.patches.size(); ++i) {
    SCOPED_TRACE("patch " + std::to_string(i));
    expect_same_polygon(from_file.patches[i].polygon, built_in.patches[i].polygon);
    const Surface& a = from_file.surfaces[from_file.patches[i].surface];
    const Surface& b = built_in.surfaces[built_in.patches[i].surface];
    EXPECT_EQ(a.reflectance, b.reflectance);
    EXPECT_EQ(a.exitance, b.exitance);
  }
  ASSERT_EQ(from_file.elements.size(), built_in.elements.size());
  for (std::size_t i = 0; i < built_in.elements.size(); ++i) {
    SCOPED_TRACE("element " + std::to_string(i));
    EXPECT_EQ(from_file.elements[i].patch, built_in.elements[i].patch);
    expect_same_polygon(from_file.elements[i].polygon, built_in.elements[i].polygon);
  }
  ASSERT_TRUE(from_file.camera && built_in.camera);
  EXPECT_EQ(from_file.camera->eye, built_in.camera->eye);
  EXPECT_EQ(from_file.camera->fov_y_degrees, built_in.camera->fov_y_degrees);
}

}  // namespace
}  // namespace gcsim::scene

namespace gcsim::radiosity {
namespace {

// The radiosity pass on cornell.toml is the radiosity application on its built-in CORNELL: the same
// radiosities bit for bit and the same simulated time, on 2 nodes with a small hemicube.
TEST(BuiltinSceneFiles, CornellFileGivesTheBuiltInRadiositiesExactly) {
  const Scene from_file = flatten(scene::to_world(scene::load_scene_file(
      std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "cornell.toml")));
  const Scene built_in = flatten(cornell_world());
  ParallelOptions options;
  options.solver.hemicube.resolution = 32;
  options.solver.energy = 0.9;
  parix::SimulationOptions sim;
  sim.config = machine::with_nodes(machine::published_machine_config(), 2);
  ParallelOutcome a, b;
  const auto run_a = parix::run_simulated(sim, [&](parix::Processor& p) { radiosity_program(p, from_file, options, &a); });
  const auto run_b = parix::run_simulated(sim, [&](parix::Processor& p) { radiosity_program(p, built_in, options, &b); });
  EXPECT_EQ(run_a.makespan, run_b.makespan);
  ASSERT_EQ(a.element_radiosity.size(), b.element_radiosity.size());
  for (std::size_t i = 0; i < a.element_radiosity.size(); ++i) EXPECT_EQ(a.element_radiosity[i], b.element_radiosity[i]) << i;
  EXPECT_EQ(a.steps.size(), b.steps.size());
}

}  // namespace
}  // namespace gcsim::radiosity
