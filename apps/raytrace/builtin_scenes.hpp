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
bool is_builtin_scene(std::string_view name);
// The built-in's scene description; throws std::invalid_argument listing the known names.
scene::SceneDescription builtin_scene_description(std::string_view name);
// A built-in scene name, or else the path of a Wavefront OBJ file (.obj) or a TOML scene file
// (.toml, apps/common/scene/README.md). Throws as the loaders do (ObjError, SceneFileError).
scene::SceneDescription load_scene_description(const std::string& name_or_path);
// The same lowered to the ray tracer's float primitives (lower_scene): one path for all three.
Scene make_builtin_scene(std::string_view name);
Scene load_scene(const std::string& name_or_path);

}  // namespace gcsim::raytrace
