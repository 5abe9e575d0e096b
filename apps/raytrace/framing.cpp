#include "apps/raytrace/framing.hpp"

#include <cmath>

namespace gcsim::raytrace {

scene::Camera frame_scene(const Bounds3& b, glm::vec3 direction, glm::vec3 up, float fov_degrees, float margin) {
  const glm::vec3 c = b.center();
  const float r = 0.5f * glm::length(b.extent());
  const float d = margin * r / std::sin(glm::radians(fov_degrees) * 0.5f);
  const glm::vec3 eye = c + d * glm::normalize(direction);
  return {glm::dvec3(eye), glm::dvec3(c), glm::dvec3(up), double(fov_degrees)};
}

}  // namespace gcsim::raytrace
