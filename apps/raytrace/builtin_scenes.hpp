#pragma once
// The built-in scenes, deterministic (fixed seeds):
//   spheres-a       512 spheres on an 8x8x8 grid, radius 0.4 of the spacing (the paper's photo 1)
//   spheres-b       the same grid with radius 0.12: mostly background between small spheres (photo 2;
//                   its A2' subtrees of 0.66 BV tests per ray say most subregions see one sphere or none)
//   spheres-random  512 spheres of random radius and position (photo 3)
//   teapot          one Utah teapot, 552 triangles (photo 4)
//   teapots         eight teapots, 4416 triangles (photo 5)
//   whitted         mirror and glass spheres and a teapot over a checkerboard, two lights (2.3)
#include <span>
#include <string>
#include <string_view>

#include "apps/common/scene/scene_description.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

std::span<const std::string_view> builtin_scene_names();
std::span<const std::string_view> paper_scene_names();  // the five of table 1, in its order
// The built-in's scene description; throws std::invalid_argument listing the known names. The six
// are registered in the scene catalogue (apps/common/scene/scene_catalogue.hpp) under these names.
scene::SceneDescription builtin_scene_description(std::string_view name);
// The same lowered to the ray tracer's float primitives (lower_scene).
Scene make_builtin_scene(std::string_view name);
// The scene catalogue's one entry (any built-in scene, any scene file format) lowered: throws as
// scene::load_scene does, or lower_scene's invalid_argument for what the ray tracer cannot show.
Scene load_scene(const std::string& name_or_path);

}  // namespace gcsim::raytrace
