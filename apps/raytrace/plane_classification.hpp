#pragma once
// Which side of a plane a box lies on: the flags of section 2.2.1 (inside, outside, crossing).
#include <glm/glm.hpp>

#include "apps/common/geometry/float_util.hpp"

#include "apps/common/geometry/bounds.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/camera.hpp"

namespace gcsim::raytrace {

enum class Side { inside, outside, crossing };

// Only "outside" drops anything, so it alone carries a margin against rounding; calling a
// crossing box "inside" merely keeps primitives that could have been dropped.
inline Side classify(const Bounds3& b, const Plane& p) {
  const glm::vec3 c = b.center();
  const glm::vec3 h = 0.5f * b.extent();
  const float s = glm::dot(p.normal, c) - p.offset;
  const float r = glm::dot(abs_components(p.normal), h);
  if (s - r > 0.0f) return Side::inside;
  const float margin = 1e-5f * (std::abs(p.offset) + glm::dot(abs_components(p.normal), abs_components(c)) + r);
  if (s + r < -margin) return Side::outside;
  return Side::crossing;
}

inline Plane flipped(const Plane& p) { return {-p.normal, -p.offset}; }

}  // namespace gcsim::raytrace
