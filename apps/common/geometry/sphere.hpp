#pragma once
// Sphere primitive. The quadratic is solved in double with the discriminant written as
// r^2 - |f - (f.d) d / |d|^2|^2, which stays accurate for radii from 1e-4 to 1e4 and for rays
// starting far away (a textbook b^2 - 4ac cancels catastrophically there).
#include <glm/glm.hpp>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/ray.hpp"

namespace gcsim::geometry {

struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;

  Bounds3 bounds() const {
    const glm::vec3 r(radius);
    return Bounds3{center - r, center + r}.padded();
  }
};

// The smallest root t with ray.tmin < t <= tmax, if any.
bool intersect_sphere(const Sphere& s, const Ray& ray, float tmax, float* t_hit);

}  // namespace gcsim::geometry
