#pragma once
// Lowers the shared description to the thesis's WORLD of entities (vertices, surfaces, patches,
// elements), which radiosity flattens into its mesh. Shapes of one `object` form one entity with one
// surface per material (in order of first use); every entity is placed once, unmoved. An object's
// ObjectLayout can declare the surface order, vertices that single-patch polygons share, and the
// instances (the radiosity app's built-in scenes need all three). A quad is
// gridded exactly as the radiosity app's EntityBuilder::quad grids it (same vertices, same record
// order, records reversed where they do not look along `facing`), so a scene file that transcribes a
// built-in scene gives the same polygons. Boxes: six outward faces on shared corners; spheres: a
// latitude-longitude tessellation (kSphereSlices x kSphereStacks patches); meshes: one patch per
// triangle. Radiosity sees only diffuse reflectance and emission: mirrors, glass, media and point or
// spot lights are not part of the WORLD.
#include "apps/common/scene/scene_description.hpp"
#include "apps/common/scene/world_format.hpp"

namespace gcsim::scene {

constexpr int kSphereSlices = 16, kSphereStacks = 8;

// A description read from a WORLD file gives that file's World (SceneDescription::source_world).
// Throws std::invalid_argument if a shape names a material that does not exist.
World to_world(const SceneDescription& description);

}  // namespace gcsim::scene
