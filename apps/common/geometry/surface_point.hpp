#pragma once
// Where a ray hit, what is needed to shade and spawn secondary rays.
#include <glm/glm.hpp>

namespace gcsim::geometry {

struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 position_error{0.0f};    // bound on the rounding error of position, per axis
  glm::vec3 geometric_normal{0.0f};  // unit, facing the side the ray came from
  glm::vec3 shading_normal{0.0f};    // unit, same side as geometric_normal
  bool entering = true;              // the ray hit the front (outward) side
};

}  // namespace gcsim::geometry
