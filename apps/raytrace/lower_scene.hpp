#pragma once
// The ray tracer's primitives from the shared scene description: spheres and triangles in float,
// polygons and boxes split into triangles, materials and point lights carried over, objects placed
// as their layouts say (scene::with_objects_placed). What Whitted
// ray tracing cannot show (participating media, glass it has no dielectric for) is refused by name,
// never dropped.
#include "apps/common/scene/scene_description.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

// Throws std::invalid_argument naming the shape, material or light it cannot lower. A glass
// material of weight g lowers to the ray tracer's dielectric with reflectance = transmittance = g
// (Fresnel splits g between the reflected and refracted rays); glass without Fresnel, or glass
// with a mirror weight besides, has no ray-tracer counterpart and is refused.
Scene lower_scene(const scene::SceneDescription& description);

// The description's point and spot lights as the ray tracer's lights (what lower_scene gives them).
std::vector<PointLight> lower_lights(const scene::SceneDescription& description);

// The bounds of the float primitives the shapes lower to, exactly Scene::bounds() of the lowered
// scene: builders frame their camera and place their lights with it before the scene is complete.
Bounds3 lowered_bounds(const scene::SceneDescription& description);

}  // namespace gcsim::raytrace
