#pragma once
// Framing a scene: a camera that sees all of it, for the built-ins, OBJ files and scene
// descriptions without a camera.
#include <glm/glm.hpp>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/scene/camera.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {

// Places the camera at `direction` (from the scene's centre) far enough back that the scene's
// bounding sphere fills the view. Computed in float; the camera's double fields hold those floats.
scene::Camera frame_scene(const Bounds3& bounds, glm::vec3 direction, glm::vec3 up, float fov_degrees, float margin = 1.0f);

}  // namespace gcsim::raytrace
