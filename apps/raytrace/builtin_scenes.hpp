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
// Throws std::invalid_argument listing the known names.
scene::SceneDescription builtin_scene_description(std::string_view name);
Scene make_builtin_scene(std::string_view name);
// A built-in scene name, or else a path to a Wavefront OBJ file.
Scene load_scene(const std::string& name_or_path);

// Places the camera at `direction` (from the scene's centre) far enough back that the scene's
// bounding sphere fills the view. Computed in float; the camera's double fields hold those floats.
scene::Camera frame_scene(const Bounds3& bounds, glm::vec3 direction, glm::vec3 up, float fov_degrees, float margin = 1.0f);

}  // namespace gcsim::raytrace
