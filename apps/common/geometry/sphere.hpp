#pragma once
// Sphere primitive. The quadratic is solved in double with the discriminant written as
// r^2 - |f - (f.d) d / |d|^2|^2, which stays accurate for radii from 1e-4 to 1e4 and for rays
// starting far away (a textbook b^2 - 4ac cancels catastrophically there).
#include <cmath>
#include <utility>

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
  SphereRay() = default;  // for arrays filled later (packet lanes)
  explicit SphereRay(const Ray& r)
      : origin(r.origin), direction(r.direction), a(glm::dot(direction, direction)), tmin(r.tmin) {}
};

// The smallest root t with ray.tmin < t <= tmax, if any. Inline: traversals call it per sphere.
inline bool intersect_sphere(const Sphere& s, const SphereRay& ray, float tmax, float* t_hit) {
  const glm::dvec3& d = ray.direction;
  const glm::dvec3 f = ray.origin - glm::dvec3(s.center);
  const double r = s.radius;
  const double a = ray.a;
  const double b = glm::dot(f, d);            // half of the usual b
  const glm::dvec3 v = f - (b / a) * d;       // f minus its projection on d
  const double disc = a * (r * r - glm::dot(v, v));
  if (disc < 0.0) return false;
  const double c = glm::dot(f, f) - r * r;
  const double q = -b - std::copysign(std::sqrt(disc), b);
  double t0 = c / q, t1 = q / a;
  if (q == 0.0) t0 = t1 = 0.0;
  if (t0 > t1) std::swap(t0, t1);
  double t = t0;
  if (t <= ray.tmin) t = t1;
  if (t <= ray.tmin || t > tmax) return false;
  *t_hit = static_cast<float>(t);
  return *t_hit > ray.tmin && *t_hit <= tmax;
}
inline bool intersect_sphere(const Sphere& s, const Ray& ray, float tmax, float* t_hit) {
  return intersect_sphere(s, SphereRay(ray), tmax, t_hit);
}

}  // namespace gcsim::geometry
