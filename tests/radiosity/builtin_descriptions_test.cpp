// The built-in scenes as scene descriptions. When they replaced the EntityBuilder code, each lowered
// to exactly its WORLD (same entities, vertex order, surfaces, records, instances, camera; checked
// field by field before that code was removed); what stays checkable: scenes/cornell.toml, written
// independently, is the same WORLD as the built-in CORNELL, and table 4.1's counts (scene_test.cpp).
#include <gtest/gtest.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/radiosity/builtin_descriptions.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/scene.hpp"
#include "tests/radiosity/same_world.hpp"

namespace gcsim::radiosity {
namespace {

using test_support::expect_same_world;

// scenes/cornell.toml transcribes the built-in CORNELL: through the scene-file loader it is the same
// WORLD, so `--scene scenes/cornell.toml` and `--scene cornell` solve one mesh.
TEST(BuiltinDescriptions, CornellFileIsTheBuiltInCornellWorld) {
  const std::string file = std::string(GCSIM_SOURCE_DIR) + "/scenes/cornell.toml";
  const World from_file = scene::to_world(scene::load_scene_file(file));
  expect_same_world(from_file, scene::to_world(cornell_description()));
  EXPECT_EQ(flatten(from_file).counts(), thesis_counts("cornell"));
  // The radiosity app's scene loader takes the file by path through the same description.
  expect_same_world(load_scene_world(file), from_file);
  expect_same_world(load_scene_world("Cornell"), from_file);
}

}  // namespace
}  // namespace gcsim::radiosity
