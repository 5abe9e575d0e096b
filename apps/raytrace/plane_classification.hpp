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
// A box as classify reads it, for boxes classified against many planes (a row's subtrees).
struct BoxCentre {
  glm::vec3 centre{0.0f}, half{0.0f}, abs_centre{0.0f};
  BoxCentre() = default;
  explicit BoxCentre(const Bounds3& b)
      : centre(b.center()), half(0.5f * b.extent()), abs_centre(abs_components(b.center())) {}
};

// classify() with the box prepared and the plane's |normal| given: the same arithmetic.
inline Side classify(const BoxCentre& b, const Plane& p, glm::vec3 abs_normal) {
  const float s = glm::dot(p.normal, b.centre) - p.offset;
  const float r = glm::dot(abs_normal, b.half);
  if (s - r > 0.0f) return Side::inside;
  const float margin = 1e-5f * (std::abs(p.offset) + glm::dot(abs_normal, b.abs_centre) + r);
  if (s + r < -margin) return Side::outside;
  return Side::crossing;
}

inline Side classify(const Bounds3& b, const Plane& p) { return classify(BoxCentre(b), p, abs_components(p.normal)); }

inline Plane flipped(const Plane& p) { return {-p.normal, -p.offset}; }

}  // namespace gcsim::raytrace
