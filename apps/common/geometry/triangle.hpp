#pragma once
// Triangle primitive with the watertight test of Woop, Benthin and Wald (2013): vertices are
// moved into a frame where the ray is the +z axis, so neighbouring triangles evaluate their
// shared edge with bit-identical arithmetic and no ray slips through a crack.
#include <glm/glm.hpp>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/ray.hpp"

namespace gcsim::geometry {

struct Triangle {
  glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};

  Bounds3 bounds() const {
    Bounds3 b = Bounds3::of_point(p0);
    b.extend(p1);
    b.extend(p2);
    return b.padded();
  }
  glm::vec3 geometric_normal() const { return glm::cross(p1 - p0, p2 - p0); }
};

// A hit with ray.tmin < t <= tmax: writes t and the barycentrics of p1 and p2.
// Degenerate (zero-area) triangles are never hit.
bool intersect_triangle(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2);

}  // namespace gcsim::geometry
