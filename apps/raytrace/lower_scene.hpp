#pragma once
// The ray tracer's primitives from the shared scene description: spheres and triangles in float,
// polygons and boxes split into triangles, materials and point lights carried over. What Whitted
// ray tracing cannot show (spot lights, participating media) is refused by name, never dropped.
#include "apps/common/scene/scene_description.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

// Throws std::invalid_argument naming the shape or light it cannot lower.
Scene lower_scene(const scene::SceneDescription& description);

}  // namespace gcsim::raytrace
