#include "apps/common/geometry/sphere.hpp"

#include <cmath>

namespace gcsim::geometry {

bool intersect_sphere(const Sphere& s, const SphereRay& ray, float tmax, float* t_hit) {
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

}  // namespace gcsim::geometry
