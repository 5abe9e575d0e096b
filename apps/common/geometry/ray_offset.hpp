#pragma once
// Where a secondary ray may start so that it cannot hit the surface it leaves: the hit point is
// moved along the geometric normal by the projection of its rounding-error box, to the side the
// new ray goes, and then one more ulp outwards (the addition itself rounds).
#include <glm/glm.hpp>

#include "apps/common/geometry/float_util.hpp"
#include "apps/common/geometry/surface_point.hpp"

namespace gcsim::geometry {

inline glm::vec3 offset_ray_origin(const SurfacePoint& sp, glm::vec3 direction) {
  const glm::vec3 n = sp.geometric_normal;
  const float d = glm::dot(abs_components(n), sp.position_error);
  glm::vec3 offset = d * n;
  if (glm::dot(direction, n) < 0) offset = -offset;
  glm::vec3 p = sp.position + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0) p[i] = next_float_up(p[i]);
    else if (offset[i] < 0) p[i] = next_float_down(p[i]);
  }
  return p;
}

}  // namespace gcsim::geometry
