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

// The ray's part of the sphere test, converted to double once per ray rather than per sphere.
struct SphereRay {
  glm::dvec3 origin, direction;
  double a;  // |direction|^2
  float tmin;
  explicit SphereRay(const Ray& r)
      : origin(r.origin), direction(r.direction), a(glm::dot(direction, direction)), tmin(r.tmin) {}
};

// The smallest root t with ray.tmin < t <= tmax, if any.
bool intersect_sphere(const Sphere& s, const SphereRay& ray, float tmax, float* t_hit);
inline bool intersect_sphere(const Sphere& s, const Ray& ray, float tmax, float* t_hit) {
  return intersect_sphere(s, SphereRay(ray), tmax, t_hit);
}

}  // namespace gcsim::geometry
